#pragma once

#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// Any-angle shortcuts over a cell-by-cell path (A* over the clearance cost), in the style of
// post-smoothing string pulling: from each kept waypoint the path jumps to the farthest later
// cell whose straight segment
//   - touches only free cells (where it passes exactly through a corner, both side cells), and
//   - costs no more than the run of cells it replaces, under A*'s own step cost
//     (length x (1 + clearance cost)),
// so a shortcut never trades clearance for length beyond what the search itself would. The
// 8-connected staircase of an A* path becomes a few straight legs, which a robot that turns in
// place at every bend drives much faster. `clearance_cost` is per cell (ClearanceCost); empty =
// length only.
std::vector<Cell> ShortcutPath(const PassabilityGrid& grid,
                               const std::vector<float>& clearance_cost,
                               const std::vector<Cell>& cells);

// Euclidean length of a polyline, in cells.
double PolylineLengthCells(const std::vector<Cell>& waypoints);

}  // namespace semnav::planning
