#include "services/planning/core/inflation.h"

#include <cmath>
#include <vector>

namespace semnav::planning {

std::vector<Cell> DiscOffsets(double radius_cells) {
  std::vector<Cell> disc;
  if (radius_cells < 0.0) return disc;
  const int r = static_cast<int>(std::floor(radius_cells));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy <= radius_cells * radius_cells) disc.push_back({dx, dy});
    }
  }
  return disc;
}

PassabilityGrid InflateObstacles(const PassabilityGrid& grid, double radius_cells) {
  if (radius_cells <= 0.0) return grid;
  const std::vector<Cell> disc = DiscOffsets(radius_cells);
  PassabilityGrid out = grid;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      if (grid.at(x, y) != 0) continue;
      // Only blocked cells on an obstacle's edge can reach free space.
      const bool edge = IsFree(grid, x + 1, y) || IsFree(grid, x - 1, y) ||
                        IsFree(grid, x, y + 1) || IsFree(grid, x, y - 1);
      if (!edge) continue;
      for (const Cell& d : disc) {
        if (out.Contains(x + d.x, y + d.y)) out.at(x + d.x, y + d.y) = 0;
      }
    }
  }
  return out;
}

}  // namespace semnav::planning
