#pragma once

#include <limits>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

inline constexpr double kUnreachable = std::numeric_limits<double>::infinity();

// Octile path distance (cells) from `from` to every cell under the
// planners' move rules (Dijkstra); kUnreachable where no path exists.
std::vector<double> OctileDistanceField(const PassabilityGrid& grid, Cell from);

// A source of a distance field: a cell and the distance already travelled to it (cells).
struct DistanceSource {
  Cell cell;
  double distance = 0.0;
};
// The same from several sources: each cell's least source distance plus path; blocked or
// outside sources are skipped.
std::vector<double> OctileDistanceField(const PassabilityGrid& grid,
                                        const std::vector<DistanceSource>& sources);

}  // namespace semnav::planning
