#include "services/planning/core/straight_jump_table.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "services/planning/core/jump_scan.h"

namespace semnav::planning {
namespace {

// Open cells '.', closed '@', stop cells 's' (open).
struct Drawn {
  BitRows open;
  BitRows stop;
};

Drawn Draw(const std::vector<std::string>& rows) {
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows[0].size());
  Drawn d{BitRows(h, w), BitRows(h, w)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (rows[y][x] != '@') d.open.Set(y, x);
      if (rows[y][x] == 's') d.stop.Set(y, x);
    }
  }
  return d;
}

// The same rules scanned cell by cell (jump_scan.h), the reference.
struct ScanSpace {
  const Drawn& d;
  bool Free(int x, int y) const {
    return x >= 0 && y >= 0 && x < d.open.columns() && y < d.open.rows() && d.open.Get(y, x);
  }
  bool Stop(Cell c) const { return d.stop.Get(c.y, c.x); }
};

TEST(StraightJumpTable, HandCheckedJumps) {
  const Drawn d = Draw({
      ".......",
      "..@....",
      ".....s.",
      ".......",
  });
  StraightJumpTable table;
  table.Build(d.open, d.stop);
  const Cell far_goal{6, 3};
  Cell found;
  // East along row 0: (3,0) has the forced neighbour (3,1) (open, with the
  // wall (2,1) behind it).
  ASSERT_TRUE(table.Jump({0, 0}, 1, 0, far_goal, &found));
  EXPECT_EQ(found, (Cell{3, 0}));
  // East along row 2: (3,2) is forced by the wall end above it, then the
  // stop cell (5,2).
  ASSERT_TRUE(table.Jump({0, 2}, 1, 0, far_goal, &found));
  EXPECT_EQ(found, (Cell{3, 2}));
  ASSERT_TRUE(table.Jump({3, 2}, 1, 0, far_goal, &found));
  EXPECT_EQ(found, (Cell{5, 2}));
  // West along row 3 runs off the grid: no jump point.
  EXPECT_FALSE(table.Jump({6, 3}, -1, 0, {0, 0}, &found));
  // ... unless the goal is on the way.
  ASSERT_TRUE(table.Jump({6, 3}, -1, 0, {1, 3}, &found));
  EXPECT_EQ(found, (Cell{1, 3}));
  // Down column 2 from row 3 (towards y = 0): the wall at (2,1) blocks.
  EXPECT_FALSE(table.Jump({2, 3}, 0, -1, far_goal, &found));
  // Up column 1 (y increasing) from row 0: (1,2) has the forced neighbour
  // (2,2), open with the wall (2,1) behind it.
  ASSERT_TRUE(table.Jump({1, 0}, 0, 1, far_goal, &found));
  EXPECT_EQ(found, (Cell{1, 2}));
}

TEST(StraightJumpTable, SameJumpsAsCellByCellScanOnRandomGrids) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 6; ++trial) {
    const int w = 40 + trial * 23;  // word boundaries inside and at the edge
    const int h = 30 + trial * 17;
    Drawn d{BitRows(h, w), BitRows(h, w)};
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (rng() % 100 < 80) d.open.Set(y, x);
        if (rng() % 100 < 3) d.stop.Set(y, x);
      }
    }
    StraightJumpTable table;
    table.Build(d.open, d.stop);
    const ScanSpace space{d};
    const Cell goal{static_cast<int>(rng() % w), static_cast<int>(rng() % h)};
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          Cell expected{-1, -1};
          Cell got{-1, -1};
          const bool scan = ScanStraight(space, {x, y}, dx, dy, goal, &expected);
          ASSERT_EQ(table.Jump({x, y}, dx, dy, goal, &got), scan) << x << "," << y;
          if (scan) {
            ASSERT_EQ(got, expected) << x << "," << y << " dir " << dx << "," << dy;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace semnav::planning
