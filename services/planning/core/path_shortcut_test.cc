#include "services/planning/core/path_shortcut.h"

#include <gtest/gtest.h>

#include <cmath>

#include "services/planning/core/clearance_cost.h"
#include "services/planning/core/test_grids.h"

namespace semnav::planning {
namespace {

// The cell-by-cell 8-connected path A* gives: diagonals first, then straight.
std::vector<Cell> Staircase(Cell from, Cell to) {
  std::vector<Cell> cells{from};
  Cell at = from;
  while (!(at == to)) {
    at.x += (to.x > at.x) - (to.x < at.x);
    at.y += (to.y > at.y) - (to.y < at.y);
    cells.push_back(at);
  }
  return cells;
}

TEST(ShortcutPath, OpenFloorBecomesOneStraightLeg) {
  const PassabilityGrid grid(12, 6, 1);
  const std::vector<Cell> path = ShortcutPath(grid, {}, Staircase({0, 0}, {10, 4}));
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(path.front(), (Cell{0, 0}));
  EXPECT_EQ(path.back(), (Cell{10, 4}));
  EXPECT_DOUBLE_EQ(PolylineLengthCells(path), std::sqrt(116.0));  // vs octile 4 sqrt2 + 6 = 11.66
}

TEST(ShortcutPath, KeepsTheCornerOfAnLShapedPath) {
  // The path goes up the left column and then right along the top row, around a block.
  const PassabilityGrid grid = GridFromRows({
      ".......",
      ".@@@@@.",
      ".@@@@@.",
      ".@@@@@.",
  });
  std::vector<Cell> cells;
  for (int y = 3; y >= 0; --y) cells.push_back({0, y});
  for (int x = 1; x <= 6; ++x) cells.push_back({x, 0});
  const std::vector<Cell> path = ShortcutPath(grid, {}, cells);
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(path[1], (Cell{0, 0}));
  for (const Cell& c : CellsAlongLegs(path))
    EXPECT_TRUE(IsFree(grid, c.x, c.y)) << c.x << "," << c.y;
}

TEST(ShortcutPath, DoesNotSqueezeThroughADiagonalCorner) {
  // (0,0) -> (2,2) crosses the corner of (0,0), (1,0), (0,1), (1,1) exactly; (0,1) is blocked,
  // so that leg is refused and the path keeps a bend: (0,0) -> (2,1) -> (2,2).
  PassabilityGrid grid = GridFromRows({
      "...",
      "@..",
      "...",
  });
  const std::vector<Cell> cells{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}};
  const std::vector<Cell> bent = ShortcutPath(grid, {}, cells);
  ASSERT_EQ(bent.size(), 3u);
  EXPECT_EQ(bent[1], (Cell{2, 1}));
  grid.at(0, 1) = 1;
  EXPECT_EQ(ShortcutPath(grid, {}, cells).size(), 2u);
}

TEST(ShortcutPath, NeverTradesClearanceForLength) {
  // A corridor of 7 free rows; the A* path over the clearance cost climbs to the middle row and
  // comes back down. A straight leg along the lower wall is shorter but dearer: not taken.
  std::vector<std::string> rows(9, std::string(40, '.'));
  rows[0] = rows[8] = std::string(40, '@');
  const PassabilityGrid grid = GridFromRows(rows);
  const std::vector<float> cost = ClearanceCost(
      grid, 0.1, {.clearance_m = 0.4, .cost_scaling_per_m = 3.0, .cost_penalty = 2.0});
  std::vector<Cell> cells = Staircase({1, 1}, {4, 4});
  for (const Cell& c : Staircase({4, 4}, {35, 4})) {
    if (!(c == cells.back())) cells.push_back(c);
  }
  for (const Cell& c : Staircase({35, 4}, {38, 1})) {
    if (!(c == cells.back())) cells.push_back(c);
  }
  const std::vector<Cell> path = ShortcutPath(grid, cost, cells);
  EXPECT_LT(path.size(), cells.size());
  bool middle_at_20 = false;
  for (const Cell& c : CellsAlongLegs(path)) {
    if (c.x == 20) middle_at_20 = c.y == 4;
  }
  EXPECT_TRUE(middle_at_20);
  // Without the cost the same cells collapse to the wall-hugging straight line.
  EXPECT_EQ(ShortcutPath(grid, {}, cells).size(), 2u);
}

}  // namespace
}  // namespace semnav::planning
