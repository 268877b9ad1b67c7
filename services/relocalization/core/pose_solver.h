#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav::relocalization {

// Parameters of the pose solve of seed 001, 3.2.
struct PoseParams {
  // A pair is an outlier when the median of |‖p_i-p_j‖ - ‖q_i-q_j‖| over the other
  // pairs j exceeds this (metres); removed one at a time, worst first.
  double outlier_distance_m = 0.2;
  // Pairs j used for each median (evenly spaced over the remaining pairs); bounds the
  // cost on large alignments. 0 = all.
  size_t max_reference_pairs = 64;
  size_t min_inliers = 3;           // fewer consistent pairs -> NOT_FOUND
  int lm_max_iterations = 50;       // Levenberg-Marquardt iterations
  double lm_initial_lambda = 1e-3;  // initial damping (relative to diag(J^T J))
  double lm_min_step = 1e-10;       // stop when the update norm falls below this
};

// q = R p + t: a query-frame point p expressed in the map frame.
struct PoseEstimate {
  Eigen::Isometry3d map_from_query = Eigen::Isometry3d::Identity();
  std::vector<size_t> inliers;  // indices of the pairs that survived outlier rejection
  double rms_residual_m = 0.0;  // over the inliers
  int iterations = 0;           // Levenberg-Marquardt iterations taken
};

// Iterative median-distance outlier rejection; returns the indices kept.
std::vector<size_t> RejectOutliersByMedianDistance(const std::vector<Eigen::Vector3d>& p,
                                                   const std::vector<Eigen::Vector3d>& q,
                                                   const PoseParams& params);

// Levenberg-Marquardt on E(R, t) = sum_i ‖q_i - (R p_i + t)‖^2 over `indices`, from `initial`.
Eigen::Isometry3d RefinePoseLevenbergMarquardt(const std::vector<Eigen::Vector3d>& p,
                                               const std::vector<Eigen::Vector3d>& q,
                                               const std::vector<size_t>& indices,
                                               const Eigen::Isometry3d& initial,
                                               const PoseParams& params, int* iterations);

// Outlier rejection, initial translation = mean displacement (R = I), then LM.
// NOT_FOUND when fewer than min_inliers pairs are consistent.
absl::StatusOr<PoseEstimate> SolvePose(const std::vector<Eigen::Vector3d>& p,
                                       const std::vector<Eigen::Vector3d>& q,
                                       const PoseParams& params);

// Rotation angle between two poses in degrees, and translation distance in metres.
double RotationDifferenceDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
double TranslationDifferenceM(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

}  // namespace semnav::relocalization
