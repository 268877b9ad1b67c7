#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "services/relocalization/core/indexed_landmarks.h"

namespace semnav::relocalization::eval {

// The comparison method: nearest-descriptor matching + RANSAC + closed-form (Umeyama)
// pose, i.e. what a descriptor-only retrieval would do (seed 001, 4.2's baseline role).
struct BaselineParams {
  int iterations = 500;              // RANSAC hypotheses (3-point samples)
  double inlier_threshold_m = 0.25;  // residual below which a pair supports a hypothesis
  size_t min_inliers = 6;            // fewer -> NOT_FOUND
  uint32_t seed = 1;
};

struct BaselineResult {
  Eigen::Isometry3d map_from_query = Eigen::Isometry3d::Identity();
  size_t inliers = 0;
};

// Rigid least-squares fit q = R p + t (Umeyama, no scale) over the given pairs.
Eigen::Isometry3d ClosedFormPose(const std::vector<Eigen::Vector3d>& p,
                                 const std::vector<Eigen::Vector3d>& q);

absl::StatusOr<BaselineResult> RelocalizeNearestDescriptorRansac(const IndexedLandmarks& query,
                                                                 const IndexedLandmarks& map,
                                                                 const BaselineParams& params);

}  // namespace semnav::relocalization::eval
