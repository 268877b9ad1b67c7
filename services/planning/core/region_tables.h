#pragma once

#include <cstdint>

#include "services/planning/core/bit_rows.h"
#include "services/planning/core/layered_grid.h"
#include "services/planning/core/straight_jump_table.h"

namespace semnav::planning {

// The per-grid preprocessing of the improved Jump A*: the grid with its
// boundary marks (the cells where jumps stop) and straight-jump table, all
// as bit rows built 64 cells per operation. Depends only on the grid
// content; immutable once built, so queries on one map (also concurrent
// ones) share it.
class RegionTables {
 public:
  explicit RegionTables(LayeredGrid grid);

  const LayeredGrid& grid() const { return grid_; }
  // Passable cells with a passable 8-neighbour of the other class (free vs
  // obstacle).
  bool Boundary(int cell) const {
    const int y = cell / grid_.width();
    return boundary_.Get(y, cell - y * grid_.width());
  }
  bool Boundary(Cell c) const { return boundary_.Get(c.y, c.x); }
  const StraightJumpTable& jumps() const { return jumps_; }
  // Memory held: the grid and the bit rows.
  size_t bytes() const;

 private:
  LayeredGrid grid_;
  BitRows boundary_;
  StraightJumpTable jumps_;
};

}  // namespace semnav::planning
