// The goal that takes a robot to look at a place where the vision model said it saw the target.
// Seed 000's UAV ends its search with a close look at what the VLM located. A sighting's EROI
// may hold no unknown cells (the depth camera mapped it from afar while the VLM made out the
// target up to 12 m away), so EROI_UTILITY's information gain would never lead there, and the
// detector, which sees objects within a few metres, would never confirm it.
#pragma once

#include <optional>
#include <vector>

#include "Eigen/Core"
#include "services/reasoning/core/navigation_interfaces.h"

namespace semnav::reasoning {

// The nearest sighting not yet looked at, and the point `inspect_distance_m` short of it on the
// straight line from the robot (the robot's own position when it is that close already: the
// executor spends such a goal at once). A sighting counts as looked at once a spent goal
// (`query.excluded_goals`) lies within inspect_distance_m + query.excluded_radius_m of it.
// nullopt when none is left. The goal keeps the robot's altitude.
std::optional<Eigen::Vector3d> SightingGoal(const std::vector<Eigen::Vector3d>& sightings,
                                            const ExplorationQuery& query,
                                            double inspect_distance_m);

}  // namespace semnav::reasoning
