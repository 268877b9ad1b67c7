#pragma once

#include <cmath>
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

// Test helper: the cells a polyline of any-angle legs passes over, sampled every 0.05 cell
// (consecutive duplicates dropped).
inline std::vector<Cell> CellsAlongLegs(const std::vector<Cell>& waypoints) {
  std::vector<Cell> out;
  if (waypoints.empty()) return out;
  out.push_back(waypoints.front());
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const Cell a = waypoints[i - 1], b = waypoints[i];
    const int samples = static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / 0.05));
    for (int k = 1; k <= samples; ++k) {
      const double t = static_cast<double>(k) / samples;
      const Cell c{static_cast<int>(std::lround(a.x + t * (b.x - a.x))),
                   static_cast<int>(std::lround(a.y + t * (b.y - a.y)))};
      if (!(c == out.back())) out.push_back(c);
    }
  }
  return out;
}

}  // namespace semnav::planning
