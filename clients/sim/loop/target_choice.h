// Picks an in-sight target for short episodes (smoke test, demo): the nearest object whose
// straight approach from the start is free on the ground-truth grid.
#pragma once

#include <optional>
#include <string>

#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/world.h"

namespace semnav::sim::loop {

struct TargetChoice {
  int object_index = -1;
  std::string label;
  double distance_m = 0.0;     // start to the object's centre
  double yaw_to_target = 0.0;  // heading from the start toward it
};

// Objects between min_m and max_m (centre distance) whose corridor to within `standoff_m` of
// the footprint is free in `grid` (inflated by the robot radius); the nearest one. Every
// footprint of the label must be at least min_m from the start too: an episode that starts in
// its success region has l_i = 0, which seed 004's SPL cannot score.
std::optional<TargetChoice> PickInSightTarget(const World& world, const GroundTruthGrid& grid,
                                              const Eigen::Vector2d& start, double min_m,
                                              double max_m, double standoff_m);

}  // namespace semnav::sim::loop
