#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "clients/sim/core/rng.h"

namespace semnav::sim {

// Planar pose: position (z is altitude of the robot base) and heading.
struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double yaw = 0.0;
};

struct OdometryDriftConfig {
  bool enabled = false;
  double scale_sigma = 0.01;            // relative error of each travelled distance
  double xy_sigma_per_sqrt_m = 0.01;    // metres of lateral/longitudinal noise per sqrt(metre)
  double yaw_sigma_per_sqrt_m = 0.005;  // radians per sqrt(metre travelled or radian turned)
};

// Dead-reckoned pose: integrates each true motion increment in the body frame with noise, so
// the error grows like a random walk with distance (and is zero when drift is disabled).
class Odometry {
 public:
  Odometry(const Pose& start, const OdometryDriftConfig& config, uint64_t seed);
  void Update(const Pose& previous_truth, const Pose& truth);
  const Pose& pose() const { return pose_; }

 private:
  OdometryDriftConfig config_;
  Pose pose_;
  Rng rng_;
};

double WrapAngle(double angle);  // to (-pi, pi]

}  // namespace semnav::sim
