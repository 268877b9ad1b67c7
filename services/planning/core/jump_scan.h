#pragma once

#include <optional>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// The jump rules of Jump Point Search without corner cutting, shared by the
// 2D JPS planner and the multi-modal Jump A*. `Space` provides
//   bool Free(int x, int y) const  -- uniform-cost traversable cell
//   bool Stop(Cell c) const        -- extra cells a jump must stop on
// A straight move forces a side cell when that side cell is free and the
// cell behind it (towards the parent) is blocked; diagonal moves have no
// forced neighbours because they need both orthogonal cells free.

template <typename Space>
bool HasStraightForcedNeighbour(const Space& space, Cell c, int dx, int dy) {
  const int sx = dy;  // perpendicular offset; one of sx, sy is zero
  const int sy = dx;
  return (space.Free(c.x + sx, c.y + sy) && !space.Free(c.x + sx - dx, c.y + sy - dy)) ||
         (space.Free(c.x - sx, c.y - sy) && !space.Free(c.x - sx - dx, c.y - sy - dy));
}

template <typename Space>
bool CanStepDiagonal(const Space& space, Cell c, int dx, int dy) {
  return space.Free(c.x + dx, c.y + dy) && space.Free(c.x + dx, c.y) && space.Free(c.x, c.y + dy);
}

// Scans from `from` along a cardinal direction; true with the jump point in
// *found when it reaches the goal, a Stop cell or a forced neighbour.
template <typename Space>
bool ScanStraight(const Space& space, Cell from, int dx, int dy, Cell goal, Cell* found) {
  Cell c = from;
  while (true) {
    c.x += dx;
    c.y += dy;
    if (!space.Free(c.x, c.y)) return false;
    if (c == goal || space.Stop(c) || HasStraightForcedNeighbour(space, c, dx, dy)) break;
  }
  *found = c;
  return true;
}

// The jump point reached from `from` in direction (dx, dy), if any.
template <typename Space>
std::optional<Cell> Jump(const Space& space, Cell from, int dx, int dy, Cell goal) {
  Cell found;
  if (dx == 0 || dy == 0) {
    if (space.JumpStraight(from, dx, dy, goal, &found)) return found;
    return std::nullopt;
  }
  Cell c = from;
  while (CanStepDiagonal(space, c, dx, dy)) {
    c.x += dx;
    c.y += dy;
    if (c == goal || space.Stop(c) || space.JumpStraight(c, dx, 0, goal, &found) ||
        space.JumpStraight(c, 0, dy, goal, &found)) {
      return c;
    }
  }
  return std::nullopt;
}

// Calls visit(dx, dy) for each direction JPS keeps at `c` when it was
// reached moving (dx, dy): the natural neighbours plus forced ones.
template <typename Space, typename Visit>
void ForEachPrunedDirection(const Space& space, Cell c, int dx, int dy, Visit visit) {
  if (dx != 0 && dy != 0) {
    visit(dx, 0);
    visit(0, dy);
    visit(dx, dy);
    return;
  }
  visit(dx, dy);
  for (int s : {-1, 1}) {
    const int sx = dx == 0 ? s : 0;
    const int sy = dy == 0 ? s : 0;
    if (space.Free(c.x + sx, c.y + sy) && !space.Free(c.x + sx - dx, c.y + sy - dy)) {
      visit(sx, sy);
      visit(sx + dx, sy + dy);
    }
  }
}

}  // namespace semnav::planning
