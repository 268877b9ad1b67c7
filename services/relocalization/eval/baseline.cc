#include "services/relocalization/eval/baseline.h"

#include <Eigen/Geometry>
#include <random>

#include "absl/strings/str_cat.h"

namespace semnav::relocalization::eval {

Eigen::Isometry3d ClosedFormPose(const std::vector<Eigen::Vector3d>& p,
                                 const std::vector<Eigen::Vector3d>& q) {
  Eigen::Matrix3Xd src(3, static_cast<Eigen::Index>(p.size()));
  Eigen::Matrix3Xd dst(3, static_cast<Eigen::Index>(q.size()));
  for (size_t i = 0; i < p.size(); ++i) {
    src.col(static_cast<Eigen::Index>(i)) = p[i];
    dst.col(static_cast<Eigen::Index>(i)) = q[i];
  }
  return Eigen::Isometry3d(Eigen::umeyama(src, dst, false));
}

absl::StatusOr<BaselineResult> RelocalizeNearestDescriptorRansac(const IndexedLandmarks& query,
                                                                 const IndexedLandmarks& map,
                                                                 const BaselineParams& params) {
  if (query.size() < 3 || map.empty()) {
    return absl::NotFoundError("too few landmarks for the baseline");
  }
  std::vector<Eigen::Vector3d> p, q;
  for (size_t i = 0; i < query.size(); ++i) {
    size_t best = 0;
    double best_s = -2.0;
    for (size_t m = 0; m < map.size(); ++m) {
      const double s = map.DescriptorSimilarity(m, query.unit_descriptor(i));
      if (s > best_s) {
        best_s = s;
        best = m;
      }
    }
    p.push_back(query.at(i).position);
    q.push_back(map.at(best).position);
  }
  std::mt19937 rng(params.seed);
  std::uniform_int_distribution<size_t> pick(0, p.size() - 1);
  const double threshold_sq = params.inlier_threshold_m * params.inlier_threshold_m;
  std::vector<size_t> best_inliers;
  for (int it = 0; it < params.iterations; ++it) {
    const size_t a = pick(rng), b = pick(rng), c = pick(rng);
    if (a == b || b == c || a == c) continue;
    const Eigen::Isometry3d h = ClosedFormPose({p[a], p[b], p[c]}, {q[a], q[b], q[c]});
    std::vector<size_t> inliers;
    for (size_t i = 0; i < p.size(); ++i) {
      if ((q[i] - h * p[i]).squaredNorm() <= threshold_sq) inliers.push_back(i);
    }
    if (inliers.size() > best_inliers.size()) best_inliers = std::move(inliers);
  }
  if (best_inliers.size() < params.min_inliers) {
    return absl::NotFoundError(absl::StrCat("baseline: best hypothesis has ", best_inliers.size(),
                                            " inliers, need ", params.min_inliers));
  }
  std::vector<Eigen::Vector3d> pi, qi;
  for (size_t i : best_inliers) {
    pi.push_back(p[i]);
    qi.push_back(q[i]);
  }
  return BaselineResult{ClosedFormPose(pi, qi), best_inliers.size()};
}

}  // namespace semnav::relocalization::eval
