#include "services/planning/core/region_tables.h"

namespace semnav::planning {
namespace {

// Cell classes for the boundary test; outside the grid counts as structure.
constexpr uint8_t kFreeClass = 1;
constexpr uint8_t kObstacleClass = 2;

}  // namespace

RegionTables::RegionTables(LayeredGrid grid) : grid_(std::move(grid)) {
  const int width = grid_.width();
  const int height = grid_.height();
  const int pw = width + 2;
  // Classes with a one-cell structure border (0), so the 8-neighbour scan
  // needs no bounds checks.
  std::vector<uint8_t> classes(static_cast<size_t>(pw) * (height + 2), 0);
  std::vector<uint8_t> structure(grid_.size(), 0);
  for (int y = 0; y < height; ++y) {
    const uint8_t* v = grid_.values().data() + static_cast<size_t>(y) * width;
    uint8_t* c = classes.data() + static_cast<size_t>(y + 1) * pw + 1;
    uint8_t* s = structure.data() + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      c[x] = v[x] == 0 ? kFreeClass : v[x] < kStructureValue ? kObstacleClass : 0;
      s[x] = v[x] >= kStructureValue;
    }
  }
  // Boundary: a passable cell with a passable 8-neighbour of the other
  // class; OR-ing the neighbours' classes shows which classes are around.
  boundary_.assign(grid_.size(), 0);
  for (int y = 0; y < height; ++y) {
    const uint8_t* c = classes.data() + static_cast<size_t>(y + 1) * pw + 1;
    const uint8_t* up = c + pw;
    const uint8_t* down = c - pw;
    uint8_t* b = boundary_.data() + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      const uint8_t around =
          up[x - 1] | up[x] | up[x + 1] | c[x - 1] | c[x + 1] | down[x - 1] | down[x] | down[x + 1];
      b[x] = c[x] != 0 && (around & (c[x] ^ (kFreeClass | kObstacleClass))) != 0;
    }
  }
  jumps_.Build(width, height, structure, boundary_);
}

}  // namespace semnav::planning
