// A sensor model of a vision-language model (issue 15): it answers the gateway's prompts from the
// ground truth of the frame it was shown, with the error rates of SimVlmConfig.
//   - seed 000's search prompt (image with printed EROI codes): "Code: X, Description: ..." naming
//     the printed code nearest the chosen clue (the target, or an instance taken for it) or, when
//     there is none, the passage (road, door) with the most pixels; "No clue or passage."
//     otherwise;
//   - seed 000's region score: an integer in [-5, 5] from the descriptions it was given;
//   - the slow path's match_target task: the candidate whose label names the target (or the
//     class an open-vocabulary phrase is a kind of: "复印机" is a printer);
//   - text embeddings in the detector's embedding space (EmbedText), the text tower a real
//     deployment pairs with its detector's image encoder.
// Everything it knows about a frame comes from the pixels the camera saw (its re-rendered view);
// an instance out of view gives no clue. Answers are a pure function of (config, prompt, frame).
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/world.h"
#include "clients/sim/vlm/code_reader.h"
#include "clients/sim/vlm/frame_log.h"
#include "clients/sim/vlm/sim_vlm_config.h"

namespace semnav::sim::vlm {

// One chat request: its text parts joined by newlines, and its decoded images (8-bit BGR).
struct VlmQuestion {
  std::string text;
  std::vector<cv::Mat> images;
};

struct VlmReply {
  std::string text;
  double latency_s = 0.0;  // simulated
  int input_tokens = 0;
  int output_tokens = 0;
};

// What the model makes out in one frame (before its errors).
struct FrameSighting {
  struct Instance {
    int object_index = -1;  // World::objects
    std::string label;
    int pixels = 0;
    cv::Point2d centroid;
  };
  struct Passage {
    std::string kind;
    int pixels = 0;
    cv::Point2d centroid;
  };
  std::vector<Instance> instances;  // at least min_pixels visible, most pixels first
  std::vector<Passage> passages;    // most pixels first
};

// True when the world label names the target as the operator said it ("red backpack" ~
// "backpack"), compared as lower-case words.
bool LabelNamesTarget(absl::string_view label, absl::string_view target);

// The search-prompt answer for what was sighted and the codes read in the frame, with the error
// model's draws from `rng` (a fixed number per call, so answers are reproducible by seed).
// A clue or passage is named only by a code printed within `max_code_distance_px` of it (a code
// further away labels another place).
std::string ChooseSearchAnswer(const FrameSighting& sighting, const std::vector<PrintedCode>& codes,
                               absl::string_view target, const SimVlmErrors& errors, Rng& rng,
                               double max_code_distance_px = 1e9);

class SimVlm {
 public:
  // `frames` must outlive the model. INVALID_ARGUMENT for a bad config.
  static absl::StatusOr<std::unique_ptr<SimVlm>> Create(const World& world, const FrameLog* frames,
                                                        SimVlmConfig config);

  // INVALID_ARGUMENT for a prompt it does not know (the proxy then falls back).
  absl::StatusOr<VlmReply> Answer(const VlmQuestion& question) const;

  // The text encoder of the detector's joint embedding space (seed 002 3.1.2: CLIP text and image
  // features compared by cosine). A text that names a class of this world (the lexicon's synonyms
  // and Chinese names first: "sofa" and "沙发" name "couch") is that class's vector plus
  // `text_embedding_noise`; any other text gets a vector of its own, near-orthogonal to every
  // class. `concept_name` says which class (or the canonical text) was encoded.
  struct TextEmbedding {
    std::vector<float> vector;
    std::string concept_name;
    double latency_s = 0.0;  // simulated, drawn per (seed, text)
  };
  TextEmbedding EmbedText(absl::string_view text) const;

  FrameSighting Sight(const RecordedFrame& frame) const;
  const SimVlmConfig& config() const { return config_; }

 private:
  SimVlm(const World& world, const FrameLog* frames, SimVlmConfig config);
  absl::StatusOr<std::string> AnswerSearch(absl::string_view target, const cv::Mat& image,
                                           uint64_t* frame_key) const;
  std::string AnswerRegionScore(absl::string_view target,
                                const std::vector<std::string>& descriptions) const;
  // `content_key` (out) keys the answer's draws: the target and the candidates' labels and
  // descriptions in order, not their ids, which mapping numbers over the life of the service, so
  // an episode's answers do not depend on the episodes mapped before it.
  absl::StatusOr<std::string> AnswerMatchTarget(absl::string_view task_json,
                                                uint64_t* content_key) const;

  World world_;
  Scene scene_;
  const FrameLog* frames_;
  SimVlmConfig config_;
};

}  // namespace semnav::sim::vlm
