#include "services/planning/core/alternative_point.h"

#include <cstdlib>

namespace semnav::planning {

std::vector<Cell> LineCells(Cell a, Cell b) {
  std::vector<Cell> cells;
  const int dx = std::abs(b.x - a.x);
  const int dy = -std::abs(b.y - a.y);
  const int sx = a.x < b.x ? 1 : -1;
  const int sy = a.y < b.y ? 1 : -1;
  int err = dx + dy;
  Cell c = a;
  while (true) {
    cells.push_back(c);
    if (c == b) break;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      c.x += sx;
    }
    if (e2 <= dx) {
      err += dx;
      c.y += sy;
    }
  }
  return cells;
}

std::optional<Cell> FindAlternativePoint(const PassabilityGrid& grid,
                                         const std::vector<uint8_t>& reachable, Cell sighting,
                                         Cell goal) {
  std::optional<Cell> best;
  long best_d2 = 0;
  for (const Cell& c : LineCells(sighting, goal)) {
    if (!IsFree(grid, c.x, c.y) || reachable[grid.Index(c)] == 0) continue;
    const long d2 = static_cast<long>(c.x - goal.x) * (c.x - goal.x) +
                    static_cast<long>(c.y - goal.y) * (c.y - goal.y);
    if (!best || d2 < best_d2) {
      best = c;
      best_d2 = d2;
    }
  }
  return best;
}

}  // namespace semnav::planning
