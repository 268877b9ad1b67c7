#include "services/reasoning/core/sighting_goal.h"

#include <algorithm>

namespace semnav::reasoning {

std::optional<Eigen::Vector3d> SightingGoal(const std::vector<Eigen::Vector3d>& sightings,
                                            const ExplorationQuery& query,
                                            double inspect_distance_m) {
  const Eigen::Vector2d robot = query.pose.position.head<2>();
  const double looked_at = inspect_distance_m + query.excluded_radius_m;
  std::optional<Eigen::Vector2d> nearest;
  for (const Eigen::Vector3d& sighting : sightings) {
    const Eigen::Vector2d place = sighting.head<2>();
    const bool spent = std::any_of(
        query.excluded_goals.begin(), query.excluded_goals.end(),
        [&](const Eigen::Vector3d& goal) { return (goal.head<2>() - place).norm() <= looked_at; });
    if (!spent && (!nearest.has_value() || (place - robot).norm() < (*nearest - robot).norm()))
      nearest = place;
  }
  if (!nearest.has_value()) return std::nullopt;
  const Eigen::Vector2d away = robot - *nearest;
  const double distance = away.norm();
  const Eigen::Vector2d goal =
      distance <= inspect_distance_m
          ? robot
          : Eigen::Vector2d(*nearest + away * (inspect_distance_m / distance));
  return Eigen::Vector3d(goal.x(), goal.y(), query.pose.position.z());
}

}  // namespace semnav::reasoning
