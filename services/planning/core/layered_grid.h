#pragma once

#include <cstdint>

#include "services/planning/core/cell_grid.h"
#include "services/planning/core/grid_search_common.h"
#include "services/planning/core/octile.h"

namespace semnav::planning {

// Hierarchical grid of seed 003 (sec. 2): 0 free (roll or fly), 1-99
// obstacle height (fly over only), >= 100 building structure (impassable).
using LayeredGrid = CellGrid<uint8_t>;
inline constexpr uint8_t kStructureValue = 100;

enum class MotionMode { kRolling, kFlying };

inline bool Passable(const LayeredGrid& grid, int x, int y) {
  return grid.Contains(x, y) && grid.at(x, y) < kStructureValue;
}

inline bool IsObstacle(uint8_t v) { return v != 0 && v < kStructureValue; }

// False when the unit move is impassable (structure entered or corner-cut);
// otherwise sets its mode: rolling only when every touched cell is free.
inline bool ClassifyMove(const LayeredGrid& grid, Cell c, int dx, int dy, MotionMode* mode) {
  if (!Passable(grid, c.x + dx, c.y + dy)) return false;
  bool flying = grid.at(c) != 0 || grid.at(c.x + dx, c.y + dy) != 0;
  if (dx != 0 && dy != 0) {
    if (!Passable(grid, c.x + dx, c.y) || !Passable(grid, c.x, c.y + dy)) return false;
    flying = flying || grid.at(c.x + dx, c.y) != 0 || grid.at(c.x, c.y + dy) != 0;
  }
  *mode = flying ? MotionMode::kFlying : MotionMode::kRolling;
  return true;
}

// Calls visit(neighbour, mode, length in cells) for each passable unit move.
template <typename Visit>
void ForEachMove(const LayeredGrid& grid, Cell c, Visit visit) {
  for (int m = 0; m < 8; ++m) {
    MotionMode mode;
    if (!ClassifyMove(grid, c, kMoveDx[m], kMoveDy[m], &mode)) continue;
    visit(Cell{c.x + kMoveDx[m], c.y + kMoveDy[m]}, mode, m < 4 ? 1.0 : kSqrt2);
  }
}

// Eq. 14 cost of one cell-length move in each mode (alpha g + beta e).
struct StepCosts {
  double roll = 0.0;
  double fly = 0.0;
  double Of(MotionMode mode) const { return mode == MotionMode::kRolling ? roll : fly; }
  friend bool operator==(const StepCosts&, const StepCosts&) = default;
};

}  // namespace semnav::planning
