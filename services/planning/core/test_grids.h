#pragma once

#include <string>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// Test helper: a passability grid drawn as text rows, '.' free, '@' blocked.
inline PassabilityGrid GridFromRows(const std::vector<std::string>& rows) {
  PassabilityGrid grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), 0);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) grid.at(x, y) = rows[y][x] == '.' ? 1 : 0;
  }
  return grid;
}

}  // namespace semnav::planning
