#pragma once

#include <cstdint>
#include <vector>

#include "services/planning/core/layered_grid.h"
#include "services/planning/core/straight_jump_table.h"

namespace semnav::planning {

// The per-grid preprocessing of the improved Jump A*: the grid with its
// boundary marks (the cells where jumps stop) and straight-jump table.
// Depends only on the grid content; immutable once built, so queries on one
// map (also concurrent ones) share it.
class RegionTables {
 public:
  explicit RegionTables(LayeredGrid grid);

  const LayeredGrid& grid() const { return grid_; }
  // Passable cells with a passable 8-neighbour of the other class (free vs
  // obstacle).
  bool Boundary(int cell) const { return boundary_[cell] != 0; }
  const StraightJumpTable& jumps() const { return jumps_; }
  // Memory held: grid, boundary marks and 4 int32 runs per cell.
  size_t bytes() const { return static_cast<size_t>(grid_.size()) * (1 + 1 + 4 * 4); }

 private:
  LayeredGrid grid_;
  std::vector<uint8_t> boundary_;
  StraightJumpTable jumps_;
};

}  // namespace semnav::planning
