#include "services/planning/core/region_tables.h"

#include "services/planning/core/grid_search_common.h"

namespace semnav::planning {

bool RegionTables::Update(const LayeredGrid& grid) {
  if (built_for_.width() == grid.width() && built_for_.height() == grid.height() &&
      built_for_.values() == grid.values()) {
    return false;
  }
  built_for_ = grid;
  structure_.assign(grid.size(), 0);
  boundary_.assign(grid.size(), 0);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      const uint8_t v = grid.at(x, y);
      if (v >= kStructureValue) {
        structure_[grid.Index(x, y)] = 1;
        continue;
      }
      for (int m = 0; m < 8; ++m) {
        const int nx = x + kMoveDx[m];
        const int ny = y + kMoveDy[m];
        if (Passable(grid, nx, ny) && IsObstacle(grid.at(nx, ny)) != IsObstacle(v)) {
          boundary_[grid.Index(x, y)] = 1;
          break;
        }
      }
    }
  }
  jumps_.Build(grid.width(), grid.height(), structure_, boundary_);
  return true;
}

}  // namespace semnav::planning
