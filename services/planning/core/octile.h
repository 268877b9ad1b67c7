#pragma once

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

inline constexpr double kSqrt2 = std::numbers::sqrt2;

// Octile distance: the exact 8-connected path length on an empty grid
// (cardinal step 1, diagonal step sqrt(2)).
inline double OctileDistance(Cell a, Cell b) {
  const int dx = std::abs(a.x - b.x);
  const int dy = std::abs(a.y - b.y);
  return dx > dy ? (dx - dy) + kSqrt2 * dy : (dy - dx) + kSqrt2 * dx;
}

}  // namespace semnav::planning
