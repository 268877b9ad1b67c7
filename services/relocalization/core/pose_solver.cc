#include "services/relocalization/core/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"

namespace semnav::relocalization {
namespace {

Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

Eigen::Matrix3d ExpSo3(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

double Cost(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q,
            const std::vector<size_t>& indices, const Eigen::Matrix3d& r, const Eigen::Vector3d& t,
            const std::vector<double>& tolerance) {
  double cost = 0.0;
  for (size_t i : indices) {
    const double t_i = ToleranceOf(tolerance, i);
    cost += (q[i] - (r * p[i] + t)).squaredNorm() / (t_i * t_i);
  }
  return cost;
}

// Median over reference pairs j != i of the internal-distance discrepancy of pair i.
double MedianDiscrepancy(const std::vector<Eigen::Vector3d>& p,
                         const std::vector<Eigen::Vector3d>& q, size_t i,
                         const std::vector<size_t>& references,
                         const std::vector<double>& tolerance, std::vector<double>& scratch) {
  scratch.clear();
  const double t_i = ToleranceOf(tolerance, i);
  for (size_t j : references) {
    if (j == i) continue;
    const double t_j = ToleranceOf(tolerance, j);
    scratch.push_back(std::abs((p[i] - p[j]).norm() - (q[i] - q[j]).norm()) /
                      std::sqrt(0.5 * (t_i * t_i + t_j * t_j)));
  }
  if (scratch.empty()) return 0.0;
  const auto mid = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() / 2);
  std::nth_element(scratch.begin(), mid, scratch.end());
  return *mid;
}

}  // namespace

std::vector<size_t> RejectOutliersByMedianDistance(const std::vector<Eigen::Vector3d>& p,
                                                   const std::vector<Eigen::Vector3d>& q,
                                                   const PoseParams& params,
                                                   const std::vector<double>& tolerance) {
  std::vector<size_t> active(p.size());
  for (size_t i = 0; i < active.size(); ++i) active[i] = i;
  std::vector<double> scratch;
  while (active.size() > 2) {
    std::vector<size_t> references = active;
    if (params.max_reference_pairs > 0 && active.size() > params.max_reference_pairs) {
      references.clear();
      const double step = static_cast<double>(active.size()) / params.max_reference_pairs;
      for (size_t r = 0; r < params.max_reference_pairs; ++r) {
        references.push_back(active[static_cast<size_t>(r * step)]);
      }
    }
    size_t worst = 0;
    double worst_error = -1.0;
    for (size_t a = 0; a < active.size(); ++a) {
      const double e = MedianDiscrepancy(p, q, active[a], references, tolerance, scratch);
      if (e > worst_error) {
        worst_error = e;
        worst = a;
      }
    }
    if (worst_error <= params.outlier_distance_m) break;
    active.erase(active.begin() + static_cast<std::ptrdiff_t>(worst));
  }
  return active;
}

Eigen::Isometry3d RefinePoseLevenbergMarquardt(const std::vector<Eigen::Vector3d>& p,
                                               const std::vector<Eigen::Vector3d>& q,
                                               const std::vector<size_t>& indices,
                                               const Eigen::Isometry3d& initial,
                                               const PoseParams& params, int* iterations,
                                               const std::vector<double>& tolerance) {
  // E(R, t) is solved about the (weighted) centroids: with t = q_mean + u - R p_mean the cost
  // is the same function, but rotation and translation steps decouple, so LM converges from
  // far (R = I, u = 0 is exactly "translation = mean displacement").
  Eigen::Vector3d p_mean = Eigen::Vector3d::Zero(), q_mean = Eigen::Vector3d::Zero();
  double weights = 0.0;
  for (size_t i : indices) {
    const double t_i = ToleranceOf(tolerance, i);
    const double w = 1.0 / (t_i * t_i);
    p_mean += w * p[i];
    q_mean += w * q[i];
    weights += w;
  }
  p_mean /= weights;
  q_mean /= weights;
  std::vector<Eigen::Vector3d> pc(p.size()), qc(q.size());
  for (size_t i : indices) {
    pc[i] = p[i] - p_mean;
    qc[i] = q[i] - q_mean;
  }
  Eigen::Matrix3d r = initial.linear();
  Eigen::Vector3d u = initial.translation() - q_mean + r * p_mean;
  double cost = Cost(pc, qc, indices, r, u, tolerance);
  double lambda = params.lm_initial_lambda;
  int it = 0;
  for (; it < params.lm_max_iterations; ++it) {
    // Residual e_i = qc_i - (R pc_i + u); under R <- exp(w) R, u <- u + du its
    // Jacobian is [ [R pc_i]_x , -I ].
    Eigen::Matrix<double, 6, 6> jtj = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> jte = Eigen::Matrix<double, 6, 1>::Zero();
    for (size_t i : indices) {
      const Eigen::Vector3d rp = r * pc[i];
      const Eigen::Vector3d e = qc[i] - (rp + u);
      Eigen::Matrix<double, 3, 6> j;
      j << Skew(rp), -Eigen::Matrix3d::Identity();
      const double t_i = ToleranceOf(tolerance, i);
      const double w = 1.0 / (t_i * t_i);
      jtj += w * (j.transpose() * j);
      jte += w * (j.transpose() * e);
    }
    Eigen::Matrix<double, 6, 6> damped = jtj;
    damped.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-9);
    const Eigen::Matrix<double, 6, 1> step = damped.ldlt().solve(-jte);
    if (!step.allFinite() || step.norm() < params.lm_min_step) break;
    const Eigen::Matrix3d r_new = ExpSo3(step.head<3>()) * r;
    const Eigen::Vector3d u_new = u + step.tail<3>();
    const double cost_new = Cost(pc, qc, indices, r_new, u_new, tolerance);
    if (cost_new < cost) {
      r = r_new;
      u = u_new;
      cost = cost_new;
      lambda = std::max(lambda * 0.1, 1e-12);
    } else {
      lambda *= 10.0;
    }
  }
  if (iterations != nullptr) *iterations = it;
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = r;
  out.translation() = q_mean + u - r * p_mean;
  return out;
}

absl::StatusOr<PoseEstimate> SolvePose(const std::vector<Eigen::Vector3d>& p,
                                       const std::vector<Eigen::Vector3d>& q,
                                       const PoseParams& params,
                                       const std::vector<double>& tolerance) {
  PoseEstimate est;
  est.inliers = RejectOutliersByMedianDistance(p, q, params, tolerance);
  if (est.inliers.size() < std::max<size_t>(params.min_inliers, 3)) {
    return absl::NotFoundError(absl::StrCat("no consistent match: ", est.inliers.size(), " of ",
                                            p.size(), " matched pairs agree, need ",
                                            std::max<size_t>(params.min_inliers, 3)));
  }
  Eigen::Vector3d mean_displacement = Eigen::Vector3d::Zero();
  double weights = 0.0;
  for (size_t i : est.inliers) {
    const double t_i = ToleranceOf(tolerance, i);
    mean_displacement += (q[i] - p[i]) / (t_i * t_i);
    weights += 1.0 / (t_i * t_i);
  }
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity();
  initial.translation() = mean_displacement / weights;
  est.map_from_query =
      RefinePoseLevenbergMarquardt(p, q, est.inliers, initial, params, &est.iterations, tolerance);
  est.rms_residual_m = std::sqrt(Cost(p, q, est.inliers, est.map_from_query.linear(),
                                      est.map_from_query.translation(), tolerance) /
                                 static_cast<double>(est.inliers.size()));
  return est;
}

double RotationDifferenceDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::AngleAxisd diff(a.linear().transpose() * b.linear());
  return std::abs(diff.angle()) * 180.0 / std::numbers::pi;
}

double TranslationDifferenceM(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

}  // namespace semnav::relocalization
