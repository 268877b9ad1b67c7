#include "services/planning/core/reachability.h"

#include "services/planning/core/grid_search_common.h"

namespace semnav::planning {

std::vector<uint8_t> ReachableFrom(const PassabilityGrid& grid, Cell from) {
  std::vector<uint8_t> reached(grid.size(), 0);
  if (!IsFree(grid, from.x, from.y)) return reached;
  std::vector<int> stack = {grid.Index(from)};
  reached[grid.Index(from)] = 1;
  while (!stack.empty()) {
    const Cell c = grid.CellAt(stack.back());
    stack.pop_back();
    for (int m = 0; m < 8; ++m) {
      if (!CanMove(grid, c.x, c.y, kMoveDx[m], kMoveDy[m])) continue;
      const int next = grid.Index(c.x + kMoveDx[m], c.y + kMoveDy[m]);
      if (reached[next] != 0) continue;
      reached[next] = 1;
      stack.push_back(next);
    }
  }
  return reached;
}

}  // namespace semnav::planning
