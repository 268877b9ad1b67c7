#pragma once

#include <cmath>
#include <optional>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// No preference among equally near cells: the first in row order wins.
struct NoTieBreak {
  long operator()(Cell) const { return 0; }
};

// The cell nearest `centre` within radius_cells (Euclidean, between cell centres) for which
// accept(cell) holds. Among equally near cells the lowest tie_key(cell) wins, then the first in
// row order (lower y, then lower x). nullopt when no accepted cell lies that close. The one
// search behind every "move a start or goal to the nearest usable cell" in planning.
template <typename Accept, typename TieKey = NoTieBreak>
std::optional<Cell> NearestCellWithin(Cell centre, double radius_cells, Accept accept,
                                      TieKey tie_key = {}) {
  const int r = static_cast<int>(std::floor(radius_cells));
  std::optional<Cell> best;
  long best_d2 = 0;
  long best_key = 0;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const long d2 = long{dx} * dx + long{dy} * dy;
      if (d2 > radius_cells * radius_cells || (best && d2 > best_d2)) continue;
      const Cell c{centre.x + dx, centre.y + dy};
      if (!accept(c)) continue;
      const long key = tie_key(c);
      if (!best || d2 < best_d2 || key < best_key) {
        best = c;
        best_d2 = d2;
        best_key = key;
      }
    }
  }
  return best;
}

}  // namespace semnav::planning
