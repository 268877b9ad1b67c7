#pragma once

#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// The offsets of every cell whose centre lies within radius_cells of the origin cell's centre.
std::vector<Cell> DiscOffsets(double radius_cells);

// Footprint inflation: blocks every cell whose centre lies within
// radius_cells of a blocked cell's centre, so a disc robot of that radius
// can be planned as a point. radius_cells <= 0 returns the grid unchanged.
PassabilityGrid InflateObstacles(const PassabilityGrid& grid, double radius_cells);

}  // namespace semnav::planning
