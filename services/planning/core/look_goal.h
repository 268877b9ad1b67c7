// Where a robot goes to look at a place its vision model said it saw the target (a sighting).
// The straight look is `distance_m` short of the sighting on the line from the robot. Where a
// cell the map knows is blocked stands on the line before that point (or within the clearance of
// it) and the point is unseen, it may be inside a building (a code printed on an EROI inside it;
// campus_quad, seed 1, start 2: the UAV flew round the library into its walls three times on the
// straight look). The look then goes to the seed-004 alternative point (alternative_point.h) on the
// line to the sighting: the cell the map knows is free, `clearance_m` from every blocked cell on
// the line, nearest to the straight look. A straight look in seen free space clear of blocked cells
// stands, and the nearest cell may lie beyond a blocked one: a low bridge or a tree the map has
// seen past is flown round, and the target beyond it stays in view.
#pragma once

#include "services/planning/core/exploration_goal.h"
#include "services/planning/core/trajectory.h"

namespace semnav::planning {

struct LookGoalConfig {
  double distance_m = 3.0;   // how far from the sighting the robot looks
  double clearance_m = 1.0;  // kept from blocked cells on the line
};

// The look goal in the map frame: the straight look unless the case above, else the alternative
// point (the centre of its cell, projected on the line); the robot's own position when it stands
// within distance_m of the sighting already or no cell qualifies. Cells off the grid are unseen.
Point2 LookGoal(const ExplorationGrid& grid, Point2 robot, Point2 sighting,
                const LookGoalConfig& config);

}  // namespace semnav::planning
