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

// `tolerance` (optional, one per pair, >= 1; empty = 1 for all): how much less exact pair i's
// positions are than the base noise (ScaleTolerance: large objects' centres). Errors are divided
// by it: the median discrepancy of pairs i, j by sqrt((t_i^2 + t_j^2) / 2), residuals by t_i
// (least-squares weight 1 / t_i^2), so the RMS residual is in units of a small object's metres.

// Iterative median-distance outlier rejection; returns the indices kept.
std::vector<size_t> RejectOutliersByMedianDistance(const std::vector<Eigen::Vector3d>& p,
                                                   const std::vector<Eigen::Vector3d>& q,
                                                   const PoseParams& params,
                                                   const std::vector<double>& tolerance = {});

// Levenberg-Marquardt on E(R, t) = sum_i ‖q_i - (R p_i + t)‖^2 / t_i^2 over `indices`, from
// `initial`.
Eigen::Isometry3d RefinePoseLevenbergMarquardt(const std::vector<Eigen::Vector3d>& p,
                                               const std::vector<Eigen::Vector3d>& q,
                                               const std::vector<size_t>& indices,
                                               const Eigen::Isometry3d& initial,
                                               const PoseParams& params, int* iterations,
                                               const std::vector<double>& tolerance = {});

// Outlier rejection, initial translation = (weighted) mean displacement (R = I), then LM.
// NOT_FOUND when fewer than min_inliers pairs are consistent.
absl::StatusOr<PoseEstimate> SolvePose(const std::vector<Eigen::Vector3d>& p,
                                       const std::vector<Eigen::Vector3d>& q,
                                       const PoseParams& params,
                                       const std::vector<double>& tolerance = {});

// Pair i's tolerance (1 when `tolerance` is empty).
inline double ToleranceOf(const std::vector<double>& tolerance, size_t i) {
  return tolerance.empty() ? 1.0 : tolerance[i];
}

// Rotation angle between two poses in degrees, and translation distance in metres.
double RotationDifferenceDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
double TranslationDifferenceM(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

}  // namespace semnav::relocalization
