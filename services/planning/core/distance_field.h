#pragma once

#include <limits>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

inline constexpr double kUnreachable = std::numeric_limits<double>::infinity();

// Octile path distance (cells) from `from` to every cell under the
// planners' move rules (Dijkstra); kUnreachable where no path exists.
std::vector<double> OctileDistanceField(const PassabilityGrid& grid, Cell from);

}  // namespace semnav::planning
