// Where a robot goes to look at a place the vision model said it saw the target (a sighting).
// Seed 000's UAV ends its search with a close look at what the VLM located. A sighting's EROI
// may hold no unknown cells (the depth camera mapped it from afar while the VLM made out the
// target up to 12 m away), so EROI_UTILITY's information gain would never lead there, and the
// detector, which sees objects within a few metres, would never confirm it. Planning, which has
// the map, answers the look goal (SelectExplorationGoalRequest.look_at); the straight line here
// is what is left without it.
#pragma once

#include <optional>
#include <vector>

#include "Eigen/Core"
#include "services/reasoning/core/navigation_interfaces.h"

namespace semnav::reasoning {

// A goal given to look at a sighting.
struct SightingLook {
  Eigen::Vector3d sighting;
  Eigen::Vector3d goal;
};

// The nearest sighting not yet looked at; nullopt when none is left. A sighting counts as looked
// at once a spent goal (`query.excluded_goals`) lies within inspect_distance_m +
// query.excluded_radius_m of it, or within query.excluded_radius_m of a goal `looks` gave for it
// (a look planning moved off the straight line, before a wall, ends farther from the sighting).
std::optional<Eigen::Vector3d> NextSighting(const std::vector<Eigen::Vector3d>& sightings,
                                            const ExplorationQuery& query,
                                            double inspect_distance_m,
                                            const std::vector<SightingLook>& looks = {});

// The point `inspect_distance_m` short of `sighting` on the straight line from the robot (the
// robot's own position when it is that close already: the executor spends such a goal at once),
// at the robot's altitude.
Eigen::Vector3d StraightLookGoal(const Eigen::Vector3d& sighting, const ExplorationQuery& query,
                                 double inspect_distance_m);

}  // namespace semnav::reasoning
