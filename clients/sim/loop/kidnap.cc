#include "clients/sim/loop/kidnap.h"

#include <cmath>

#include "clients/sim/core/nearest_goal_search.h"

namespace semnav::sim::loop {

std::optional<Pose> KidnapDestination(const GroundTruthGrid& grid, const Pose& robot,
                                      const std::vector<Eigen::Vector2d>& path,
                                      const KidnapConfig& config, Rng& rng) {
  const Eigen::Vector2d from = robot.position.head<2>();
  const double near_path_sq = config.max_from_path_m * config.max_from_path_m;
  std::vector<Eigen::Vector2d> candidates;
  // The search never stops (no cell is its goal): it visits every cell the robot reaches, in a
  // fixed order, and keeps those that qualify.
  NearestReachableGoal(grid, from, [&](const Eigen::Vector2d& at) {
    const double distance = (at - from).norm();
    if (distance < config.min_distance_m || distance > config.max_distance_m) return false;
    for (const Eigen::Vector2d& p : path) {
      if ((p - at).squaredNorm() <= near_path_sq) {
        candidates.push_back(at);
        break;
      }
    }
    return false;
  });
  if (candidates.empty()) return std::nullopt;
  const Eigen::Vector2d to =
      candidates[static_cast<size_t>(rng.UniformInt(0, static_cast<int>(candidates.size()) - 1))];
  return Pose{Eigen::Vector3d(to.x(), to.y(), robot.position.z()), rng.Uniform(-M_PI, M_PI)};
}

}  // namespace semnav::sim::loop
