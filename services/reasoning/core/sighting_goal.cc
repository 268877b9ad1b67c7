#include "services/reasoning/core/sighting_goal.h"

#include <algorithm>

namespace semnav::reasoning {
namespace {

bool NearAny(const std::vector<Eigen::Vector3d>& goals, const Eigen::Vector2d& place,
             double radius) {
  return std::any_of(goals.begin(), goals.end(), [&](const Eigen::Vector3d& goal) {
    return (goal.head<2>() - place).norm() <= radius;
  });
}

}  // namespace

std::optional<Eigen::Vector3d> NextSighting(const std::vector<Eigen::Vector3d>& sightings,
                                            const ExplorationQuery& query,
                                            double inspect_distance_m,
                                            const std::vector<SightingLook>& looks) {
  const Eigen::Vector2d robot = query.pose.position.head<2>();
  const auto spent = [&](const Eigen::Vector3d& sighting) {
    if (NearAny(query.excluded_goals, sighting.head<2>(),
                inspect_distance_m + query.excluded_radius_m)) {
      return true;
    }
    return std::any_of(looks.begin(), looks.end(), [&](const SightingLook& look) {
      return look.sighting == sighting &&
             NearAny(query.excluded_goals, look.goal.head<2>(), query.excluded_radius_m);
    });
  };
  std::optional<Eigen::Vector3d> nearest;
  for (const Eigen::Vector3d& sighting : sightings) {
    if (spent(sighting)) continue;
    if (!nearest.has_value() ||
        (sighting.head<2>() - robot).norm() < (nearest->head<2>() - robot).norm()) {
      nearest = sighting;
    }
  }
  return nearest;
}

Eigen::Vector3d StraightLookGoal(const Eigen::Vector3d& sighting, const ExplorationQuery& query,
                                 double inspect_distance_m) {
  const Eigen::Vector2d robot = query.pose.position.head<2>();
  const Eigen::Vector2d place = sighting.head<2>();
  const Eigen::Vector2d away = robot - place;
  const double distance = away.norm();
  const Eigen::Vector2d goal =
      distance <= inspect_distance_m
          ? robot
          : Eigen::Vector2d(place + away * (inspect_distance_m / distance));
  return Eigen::Vector3d(goal.x(), goal.y(), query.pose.position.z());
}

}  // namespace semnav::reasoning
