#include "services/planning/core/region_tables.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "services/planning/core/random_layered_map.h"

namespace semnav::planning {
namespace {

// '.' free, digits obstacle, '#' structure.
LayeredGrid Layered(const std::vector<std::string>& rows) {
  LayeredGrid grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), 0);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      const char c = rows[y][x];
      grid.at(x, y) = c == '.'   ? 0
                      : c == '#' ? kStructureValue
                                 : static_cast<uint8_t>(10 * (c - '0'));
    }
  }
  return grid;
}

std::vector<std::string> BoundaryMap(const RegionTables& tables) {
  const LayeredGrid& g = tables.grid();
  std::vector<std::string> rows(g.height(), std::string(g.width(), '-'));
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (tables.Boundary(Cell{x, y})) rows[y][x] = 'B';
      EXPECT_EQ(tables.Boundary(g.Index(x, y)), tables.Boundary(Cell{x, y}));
    }
  }
  return rows;
}

TEST(RegionTables, BoundaryIsWhereFreeAndObstacleCellsTouch) {
  // Structure (#) is neither class: the free cells next to it are not
  // boundary, nor is the structure itself. Obstacle heights 10-90 (digits
  // 1-9; byte values above 99 are structure).
  const RegionTables tables(Layered({
      "........#",
      "...5....#",
      "........#",
      "......99#",
      "......99#",
  }));
  EXPECT_EQ(BoundaryMap(tables), (std::vector<std::string>{
                                     "--BBB----", "--BBB----", "--BBBBBB-", "-----BBB-",
                                     "-----BB--",  // (7,4) touches no free cell
                                 }));
}

// A cell is boundary exactly when it is passable and one of its 8
// neighbours is passable of the other class (cell by cell reference).
TEST(RegionTables, BoundaryMatchesTheDefinitionOnARandomMap) {
  const RandomLayeredMap map = MakeRandomLayeredMap({.size_m = 7.0, .obstacle_count = 30});
  const LayeredGrid& g = map.grid;
  const RegionTables tables(g);
  auto cls = [&](int x, int y) {
    if (!g.Contains(x, y) || g.at(x, y) >= kStructureValue) return 0;
    return g.at(x, y) == 0 ? 1 : 2;
  };
  int boundary_cells = 0;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      bool expected = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int n = cls(x + dx, y + dy);
          expected = expected || (cls(x, y) != 0 && n != 0 && n != cls(x, y));
        }
      }
      ASSERT_EQ(tables.Boundary(Cell{x, y}), expected) << x << "," << y;
      boundary_cells += expected;
    }
  }
  EXPECT_GT(boundary_cells, 100);  // the map does have obstacles
}

}  // namespace
}  // namespace semnav::planning
