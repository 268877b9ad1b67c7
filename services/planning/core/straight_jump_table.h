#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// Precomputed straight jumps (the JPS+ idea) for one query's grid: for each
// cell and cardinal direction, how far a straight jump goes. Building costs
// four linear passes; each straight jump is then O(1), which keeps the
// diagonal jumps (a straight probe per diagonal step) linear.
// A cell is an event for a direction when it is a stop cell or has a forced
// neighbour for that direction (side cell open, the cell behind it blocked).
class StraightJumpTable {
 public:
  // blocked/stop: one byte per cell (row-major), non-zero = true.
  void Build(int width, int height, const std::vector<uint8_t>& blocked,
             const std::vector<uint8_t>& stop);

  // Jump from `from` along (dx, dy) (one of them zero). True with the event
  // cell, or `goal` if the run reaches it first, in *found.
  bool Jump(Cell from, int dx, int dy, Cell goal, Cell* found) const;

 private:
  int width_ = 0;
  int height_ = 0;
  // Per direction (+x, -x, +y, -y) and cell: > 0, the event cell that many
  // steps away; <= 0, -value open steps and then a blocked cell.
  // Allocated without zero-filling: Build writes every entry, and the fill
  // would double the table's memory traffic.
  std::unique_ptr<int32_t[]> runs_[4];
};

}  // namespace semnav::planning
