// The simulated vision-language model's sensor model: what it can recognise in a frame, how it
// errs, and how long it takes. Defaults and their sources: docs/simulation.md, "Simulated VLM".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/status.h"

namespace semnav::sim::vlm {

struct SimVlmErrors {
  double miss_rate = 0.15;           // a visible target is not reported as a clue
  double confusion_rate = 0.03;      // each visible non-target instance is taken for the target
  double hallucination_rate = 0.05;  // a frame with no true clue gets one at a random printed code
  double code_off_by_one_rate = 0.10;  // the reported code names a neighbouring cell
};

// Log-normal latency: median exp(mu), spread sigma (of the log), capped.
struct SimVlmLatency {
  double vision_median_s = 1.4;  // mean 1.51 s with sigma 0.4 (seed 000 table 6)
  double text_median_s = 0.32;   // mean 0.35 s (seed 000 table 6)
  // One call to the text encoder (POST <base>/embeddings): a CLIP-class text tower served on the
  // ground station answers in tens of milliseconds (assumed; no seed gives a figure).
  double embedding_median_s = 0.03;
  double sigma = 0.4;
  double max_s = 10.0;
};

struct SimVlmConfig {
  SimVlmErrors errors;
  SimVlmLatency latency;
  uint64_t seed = 1;
  int min_pixels = 12;        // pixels an instance needs to be recognisable (160 x 120 frames)
  double max_range_m = 40.0;  // what the model can make out, metres of z-depth
  // A clue is named by the printed code nearest it only within this many pixels (two code widths
  // at the gateway's font on 160 x 120 frames); a farther clue lies beyond the codes' 3-12 m.
  double max_code_distance_px = 40.0;
  // Obstacle kinds the prompt's "passages (doors, windows, roads)" are.
  std::vector<std::string> passage_kinds = {"road", "door", "window", "gate"};
  // How the gateway prints the codes (services/reasoning InverseMappingConfig).
  double font_scale = 0.5;
  int font_thickness = 1;
  // A received image is the recorded frame it differs least from, if at most this share of its
  // pixels differ (the printed codes).
  double max_changed_share = 0.5;
  // Usage reported per call (seed 000 table 6: qwen3-vl-plus 1083 in / 18 out; qwen-plus 381 / 1).
  int vision_input_tokens = 1083;
  int text_input_tokens = 381;
  // The text tower of the detector's embedding space (POST <base>/embeddings): the simulated
  // detector's per-class appearance vectors (clients/sim/core DetectorConfig embedding_dim and
  // embedding_seed; a deployment pairs its detector's image encoder with the same model's text
  // encoder, seed 002 3.1.2's CLIP ViT-B/32). The bench copies these from its detector.
  int embedding_dim = 64;
  uint64_t embedding_seed = 1;
  // A text vector is its class vector plus noise of this norm, like one detection's (the
  // detector's embedding_noise 0.3: cosine about 0.96 to the class); drawn per (seed, text).
  double text_embedding_noise = 0.3;
  std::string api_key;  // "" = no key required (a local server)
};

// The error model at recognition accuracy `accuracy` in [0, 1] (the VLM-quality sweep): miss rate
// 1 - accuracy, and the other three rates scaled with it in the defaults' proportions, so the
// defaults are accuracy 0.85 (miss 0.15: confusion 0.03, hallucination 0.05, off by one 0.10).
SimVlmErrors ErrorsAtAccuracy(double accuracy);

// INVALID_ARGUMENT naming the field: rates outside [0, 1], non-positive latencies, sizes < 1.
absl::Status ValidateSimVlmConfig(const SimVlmConfig& config);

}  // namespace semnav::sim::vlm
