#include "services/relocalization/eval/metrics.h"

#include <algorithm>
#include <cmath>

#include "services/relocalization/core/pose_solver.h"

namespace semnav::relocalization::eval {
namespace {

// Nearest-rank percentile (q in [0, 1]); 0 for an empty list.
double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t rank = static_cast<size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::clamp<size_t>(rank, 1, v.size()) - 1];
}

}  // namespace

PoseError ComputePoseError(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& truth) {
  const Eigen::Vector3d d = (estimate.translation() - truth.translation()).cwiseAbs();
  return {d.x(), d.y(), d.z(), d.norm(), RotationDifferenceDeg(estimate, truth)};
}

MethodSummary Summarize(const std::vector<KeyframeOutcome>& outcomes, const SuccessBounds& bounds) {
  MethodSummary s;
  if (outcomes.empty()) return s;
  std::vector<double> ex, ey, ez, ep, er, ms, cpu_ms;
  size_t answered = 0;
  for (const KeyframeOutcome& o : outcomes) {
    ms.push_back(o.ms);
    cpu_ms.push_back(o.cpu_ms);
    if (!o.answered) continue;
    ++answered;
    if (o.error.ep > bounds.max_position_error_m || o.error.er > bounds.max_rotation_error_deg) {
      continue;
    }
    ex.push_back(o.error.ex);
    ey.push_back(o.error.ey);
    ez.push_back(o.error.ez);
    ep.push_back(o.error.ep);
    er.push_back(o.error.er);
  }
  const double n = static_cast<double>(outcomes.size());
  s.recall = static_cast<double>(ep.size()) / n;
  s.answered_rate = static_cast<double>(answered) / n;
  s.median_ex = Percentile(ex, 0.5);
  s.median_ey = Percentile(ey, 0.5);
  s.median_ez = Percentile(ez, 0.5);
  s.median_pos_err_m = Percentile(ep, 0.5);
  s.median_rot_err_deg = Percentile(er, 0.5);
  s.ms_median = Percentile(ms, 0.5);
  s.ms_p99 = Percentile(ms, 0.99);
  s.cpu_ms_median = Percentile(cpu_ms, 0.5);
  s.cpu_ms_p99 = Percentile(cpu_ms, 0.99);
  return s;
}

}  // namespace semnav::relocalization::eval
