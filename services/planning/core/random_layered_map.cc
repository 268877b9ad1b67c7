#include "services/planning/core/random_layered_map.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace semnav::planning {
namespace {

void ClearDisk(LayeredGrid* grid, Cell center, int radius) {
  for (int y = center.y - radius; y <= center.y + radius; ++y) {
    for (int x = center.x - radius; x <= center.x + radius; ++x) {
      const int dx = x - center.x;
      const int dy = y - center.y;
      if (grid->Contains(x, y) && dx * dx + dy * dy <= radius * radius) grid->at(x, y) = 0;
    }
  }
}

}  // namespace

RandomLayeredMap MakeRandomLayeredMap(const RandomLayeredMapSpec& spec) {
  const int n = static_cast<int>(std::lround(spec.size_m / spec.resolution_m));
  RandomLayeredMap map{LayeredGrid(n, n, 0), {}, {}};
  LayeredGrid& grid = map.grid;
  for (int i = 0; i < n; ++i) {
    grid.at(i, 0) = grid.at(i, n - 1) = grid.at(0, i) = grid.at(n - 1, i) = kStructureValue;
  }
  std::mt19937 rng(spec.seed);
  std::uniform_real_distribution<double> side(spec.min_obstacle_side_m, spec.max_obstacle_side_m);
  std::uniform_real_distribution<double> height(spec.min_obstacle_height_m,
                                                spec.max_obstacle_height_m);
  std::uniform_real_distribution<double> where(0.0, spec.size_m);
  for (int k = 0; k < spec.obstacle_count; ++k) {
    const int w = std::max(1, static_cast<int>(side(rng) / spec.resolution_m));
    const int h = std::max(1, static_cast<int>(side(rng) / spec.resolution_m));
    const int x0 = static_cast<int>(where(rng) / spec.resolution_m);
    const int y0 = static_cast<int>(where(rng) / spec.resolution_m);
    // Eq. 3: h_o = 100 (z - h_f) / (h_c - h_f), kept inside 1-99.
    const double value = std::clamp(100.0 * height(rng) / spec.ceiling_m, 1.0, 99.0);
    for (int y = std::max(1, y0); y < std::min(n - 1, y0 + h); ++y) {
      for (int x = std::max(1, x0); x < std::min(n - 1, x0 + w); ++x) {
        grid.at(x, y) = static_cast<uint8_t>(std::lround(value));
      }
    }
  }
  const int margin = static_cast<int>(std::lround(2.0 / spec.resolution_m));
  map.start = {margin, margin};
  map.goal = {n - 1 - margin, n - 1 - margin};
  const int clear = static_cast<int>(std::lround(spec.clear_radius_m / spec.resolution_m));
  ClearDisk(&grid, map.start, clear);
  ClearDisk(&grid, map.goal, clear);
  return map;
}

}  // namespace semnav::planning
