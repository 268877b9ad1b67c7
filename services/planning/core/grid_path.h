#pragma once

#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// A path as waypoints; consecutive waypoints are joined by a straight or
// 45-degree run of cells (A* gives every cell, JPS gives jump points only),
// except GridPlanner's clearance paths, whose legs are any-angle (ShortcutPath).
struct GridPath {
  std::vector<Cell> waypoints;
  double length_cells = 0.0;  // octile length in cell units
  int expansions = 0;         // nodes taken off the open list
};

// Every cell along the runs between waypoints, start and goal included.
std::vector<Cell> ExpandWaypoints(const std::vector<Cell>& waypoints);

}  // namespace semnav::planning
