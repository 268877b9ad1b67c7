#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "clients/sim/core/scene.h"
#include "clients/sim/core/view_renderer.h"
#include "clients/sim/core/world.h"

// A simulated object detector working from what the camera really sees: an object is
// detectable when enough of its pixels are unoccluded in the rendered view.
namespace semnav::sim {

struct DetectorConfig {
  int min_pixels = 150;               // unoccluded pixels an object needs to be detectable
  double max_range = 6.0;             // metres (median depth of its pixels)
  double miss_rate = 0.1;             // probability a detectable object is not reported
  double false_positive_rate = 0.05;  // expected false detections per frame (Poisson)
  double confusion_rate = 0.05;       // probability a reported object gets another label
  double box_noise_px = 3.0;          // std-dev added to each box edge
  double depth_noise_m = 0.05;        // std-dev added to the reported depth
  int embedding_dim = 64;
  double embedding_noise = 0.3;  // cosine to the class vector about 1/sqrt(1+0.09) = 0.96
  uint64_t embedding_seed = 1;   // fixes the per-class vectors (shared by all frames)
  // Labels false positives and confusions draw from, in addition to the world's labels.
  std::vector<std::string> distractor_labels = {"chair", "potted plant", "tv",     "bed",
                                                "couch", "toilet",       "bottle", "car"};
  // Obstacle kinds reported as "stuff" (COCO-Stuff's road, river), the way a panoptic detector
  // or seed 000's VLM names the surroundings: one segment per kind per frame, never a target.
  std::vector<std::string> stuff_kinds = {"road", "river"};
};

struct Detection {
  std::string label;
  double score = 0.0;    // confidence 0..1
  Eigen::Vector4i box;   // pixels: x_min, y_min, x_max, y_max (inclusive)
  double depth_m = 0.0;  // median z-depth of the object's pixels (+ noise)
  Eigen::Vector3d position_camera = Eigen::Vector3d::Zero();  // optical frame, metres
  std::vector<float> embedding;  // unit vector; appearance of the TRUE class
  int pixel_count = 0;
  int object_index = -1;  // ground truth: World::objects index, -1 = false positive or stuff
};

struct DetectionFrame {
  std::vector<Detection> detections;
  // Per pixel: 1 + index in `detections` whose object covers it, 0 = none (no masks for
  // false positives, which have only a box).
  std::vector<uint16_t> mask;
};

DetectionFrame DetectObjects(const RenderedView& view, const Scene& scene, const World& world,
                             const DetectorConfig& config, uint64_t seed);

}  // namespace semnav::sim
