#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// Seed 004 sec. 2.5: when the goal sits in or behind an obstacle, plan to
//   p_subgoal = argmin_{p in Line(p_sight, p_goal), p free} dis(p, p_goal)
// where p_sight is where the robot stood when it first saw the goal (so
// the line is known to be observable). We also require p to be reachable
// (reachable[p] != 0, see ReachableFrom), since an unreachable free cell
// would only move the failure. nullopt when no line cell qualifies.
std::optional<Cell> FindAlternativePoint(const PassabilityGrid& grid,
                                         const std::vector<uint8_t>& reachable, Cell sighting,
                                         Cell goal);

// The cells of the digital line from a to b (Bresenham), a first, b last.
std::vector<Cell> LineCells(Cell a, Cell b);

}  // namespace semnav::planning
