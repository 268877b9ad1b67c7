#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "absl/status/statusor.h"
#include "services/relocalization/core/indexed_landmarks.h"
#include "services/relocalization/core/landmark_matcher.h"
#include "services/relocalization/core/pose_solver.h"

namespace semnav::relocalization {

// Parameters of one relocalization (seed 001, 3.1-3.2).
struct RelocalizationParams {
  MatchParams match;
  PoseParams pose;
  int rematch_rounds = 2;  // stage-2 re-match + solve rounds, each under the latest pose
  double reliable_translation_m = 1.0;  // final vs initial pose: max translation change
  double reliable_rotation_deg = 10.0;  // final vs initial pose: max rotation change
  size_t reliable_min_inliers = 12;     // fewer final inliers is never reliable
};

struct RelocalizationResult {
  Eigen::Isometry3d map_from_query = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d initial_map_from_query = Eigen::Isometry3d::Identity();  // from stage 1
  std::vector<Match> matches;   // stage-2 pairs the final pose was solved from
  std::vector<size_t> inliers;  // indices into `matches` kept by outlier rejection
  double rms_residual_m = 0.0;
  bool reliable = false;  // final pose within the thresholds of the initial one, enough inliers
};

// Finds the pose of the query landmarks (e.g. a keyframe's, or robot B's whole map)
// in the map: stage-1 retrieval with early stop after m matches -> initial pose ->
// stage-2 re-match of all query landmarks under it -> pose (repeated rematch_rounds
// times, each round under the latest pose) -> reliability check against the initial pose.
// If the first m matches are inconsistent, retrieval continues with m more.
// NOT_FOUND (with the reason) for fewer than 3 landmarks on either side or when no
// consistent set of matches exists.
absl::StatusOr<RelocalizationResult> Relocalize(const IndexedLandmarks& query,
                                                const IndexedLandmarks& map,
                                                const RelocalizationParams& params);

}  // namespace semnav::relocalization
