#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace semnav::relocalization::eval {

// Errors of seed 001, 4: per-axis e_x e_y e_z, position e_p (m), rotation e_r (deg).
struct PoseError {
  double ex = 0, ey = 0, ez = 0, ep = 0, er = 0;
};
PoseError ComputePoseError(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& truth);

// A keyframe counts as relocalized when the method answered (and called its answer
// reliable) and the answer is within these bounds of the truth.
struct SuccessBounds {
  double max_position_error_m = 0.5;
  double max_rotation_error_deg = 5.0;
};

struct KeyframeOutcome {
  bool answered = false;  // a (reliable) pose was returned
  PoseError error;        // valid when answered
  double ms = 0.0;        // wall time of the call
  double cpu_ms = 0.0;    // CPU time of the calling thread (immune to other processes' load)
};

struct MethodSummary {
  double recall = 0.0;         // relocalized keyframes / all keyframes (seed 001, 4)
  double answered_rate = 0.0;  // answered keyframes / all (incl. wrong answers)
  double median_ex = 0, median_ey = 0, median_ez = 0;
  double median_pos_err_m = 0.0;  // over relocalized keyframes
  double median_rot_err_deg = 0.0;
  double ms_median = 0.0;  // wall time, over all keyframes
  double ms_p99 = 0.0;
  double cpu_ms_median = 0.0;  // thread CPU time, over all keyframes
  double cpu_ms_p99 = 0.0;
};
MethodSummary Summarize(const std::vector<KeyframeOutcome>& outcomes, const SuccessBounds& bounds);

}  // namespace semnav::relocalization::eval
