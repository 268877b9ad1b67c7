// Scene-graph instances as relocalization landmarks (seed 001, 1.1): the stable object points a
// robot's landmark map is built from, derived from what mapping already tracks, so the map fills
// itself while the robot maps. One implementation, used by the live push and by SaveMap.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "services/mapping/core/scene_types.h"
#include "services/relocalization/core/landmark.h"

namespace semnav::mapping {

// How instances become landmarks (YAML "mapping.landmarks"; docs/algorithms/relocalization.md).
struct SceneLandmarkConfig {
  // Seed 001 keeps object points tracked over several frames: an instance is a landmark once
  // this many detections were fused into it.
  int min_detections = 3;
  // The label block of the descriptor: one entry per label, in this order (the seed's N
  // classes); each holds the label's share of the instance's summed detector scores. Empty =
  // no label block. Every robot sharing maps must use the same list.
  std::vector<std::string> labels;
  // Length of the embedding block (the detector's embedding length); 0 = no embedding block.
  // Instances whose embedding has another length get zeros there.
  int embedding_dim = 64;
  // The unit embedding is scaled by this, so the label block (shares up to 1) keeps the
  // descriptor's arg-max, the hash key of seed 001 3.1, while the embedding still moves cosines.
  double embedding_weight = 0.5;
};

// INVALID_ARGUMENT naming the offending key (min_detections, labels[i], embedding_dim,
// embedding_weight) unless the descriptor has 1..kMaxDescriptorDim entries.
absl::Status ValidateSceneLandmarkConfig(const SceneLandmarkConfig& config);

// Descriptor length of every landmark made with `config`: labels + embedding_dim.
size_t SceneLandmarkDescriptorDim(const SceneLandmarkConfig& config);

// A landmark and the scene-graph instance it describes.
struct SceneLandmark {
  uint64_t object_id = 0;
  relocalization::Landmark landmark;  // id 0: not yet stored in a landmark map
};

// The stable instances of `objects` (detection_count >= min_detections, not pose_untrusted: seen
// while the robot was lost, see SceneObject::pose_untrusted) as landmarks, in input
// order: position = instance centre, scale = its box diagonal (metres), descriptor = [label
// shares | embedding_weight x unit embedding], observations = detections. An instance is left
// out when its descriptor would be all zero or the landmark fails ValidateLandmark (a
// non-finite or out-of-range centre, an empty box). `config` must be valid.
std::vector<SceneLandmark> LandmarksFromScene(const std::vector<SceneObject>& objects,
                                              const SceneLandmarkConfig& config);

// The instances not observed during the last `settle_s` seconds before the newest observation of
// `objects` (all of them when settle_s is 0), in input order.
std::vector<SceneObject> SettledInstances(const std::vector<SceneObject>& objects, double settle_s);

}  // namespace semnav::mapping
