#pragma once

#include <cstdint>
#include <vector>

#include "services/planning/core/layered_grid.h"
#include "services/planning/core/straight_jump_table.h"

namespace semnav::planning {

// The per-grid preprocessing of the improved Jump A*: boundary marks (the
// cells where jumps stop) and the straight-jump table. Depends only on the
// grid content, so it is rebuilt only when that content changes; the
// service plans many queries on one map.
class RegionTables {
 public:
  // Rebuilds the tables unless `grid` has the content they were built for;
  // returns whether it rebuilt.
  bool Update(const LayeredGrid& grid);

  // Passable cells with a passable 8-neighbour of the other class (free vs
  // obstacle).
  bool Boundary(int cell) const { return boundary_[cell] != 0; }
  const StraightJumpTable& jumps() const { return jumps_; }

 private:
  LayeredGrid built_for_;
  std::vector<uint8_t> structure_;
  std::vector<uint8_t> boundary_;
  StraightJumpTable jumps_;
};

}  // namespace semnav::planning
