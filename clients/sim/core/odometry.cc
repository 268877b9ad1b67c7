#include "clients/sim/core/odometry.h"

#include <cmath>
#include <numbers>

namespace semnav::sim {

double WrapAngle(double angle) {
  angle = std::remainder(angle, 2.0 * std::numbers::pi);
  return angle <= -std::numbers::pi ? angle + 2.0 * std::numbers::pi : angle;
}

Odometry::Odometry(const Pose& start, const OdometryDriftConfig& config, uint64_t seed)
    : config_(config), pose_(start), rng_(seed) {}

void Odometry::Update(const Pose& previous_truth, const Pose& truth) {
  const Eigen::Vector2d step_world = (truth.position - previous_truth.position).head<2>();
  const double c = std::cos(previous_truth.yaw), s = std::sin(previous_truth.yaw);
  Eigen::Vector2d step_body(c * step_world.x() + s * step_world.y(),
                            -s * step_world.x() + c * step_world.y());
  double turn = WrapAngle(truth.yaw - previous_truth.yaw);
  if (config_.enabled) {
    const double distance = step_body.norm();
    const double root = std::sqrt(distance);
    step_body *= 1.0 + rng_.Normal(0.0, config_.scale_sigma);
    const double along = rng_.Normal(0.0, config_.xy_sigma_per_sqrt_m * root);
    const double across = rng_.Normal(0.0, config_.xy_sigma_per_sqrt_m * root);
    step_body += Eigen::Vector2d(along, across);
    turn += rng_.Normal(0.0, config_.yaw_sigma_per_sqrt_m * std::sqrt(distance + std::abs(turn)));
  }
  const double oc = std::cos(pose_.yaw), os = std::sin(pose_.yaw);
  pose_.position.x() += oc * step_body.x() - os * step_body.y();
  pose_.position.y() += os * step_body.x() + oc * step_body.y();
  pose_.position.z() = truth.position.z();
  pose_.yaw = WrapAngle(pose_.yaw + turn);
}

}  // namespace semnav::sim
