#pragma once

#include <cstdint>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// Cells reachable from `from` under the planners' move rules (8-connected,
// no corner cutting): one byte per cell, 1 = reachable. All zero when
// `from` is outside the grid or blocked.
std::vector<uint8_t> ReachableFrom(const PassabilityGrid& grid, Cell from);

}  // namespace semnav::planning
