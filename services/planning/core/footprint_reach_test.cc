#include "services/planning/core/footprint_reach.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "services/planning/core/distance_field.h"
#include "services/planning/core/test_grids.h"

namespace semnav::planning {
namespace {

// Rows are y (GridFromRows: '.' free, anything else blocked: an obstacle or unknown space); every
// grid here is the same upside down. Columns 0-9 free, 10-11 unknown: the frontier is column 9.
const std::vector<std::string> kRoomEdge = {
    "..........##", "..........##", "..........##", "..........##",
    "..........##", "..........##", "..........##",
};

TEST(FootprintReach, AFrontierCellIsReachedFromTheEdgeOfTheInflation) {
  // Radius 1 blocks column 9; (9, 3) is reached from (8, 3): 6 cells from (2, 3), then 1.
  // (7, 3) and (6, 3) are as short a way (5 + 2, 4 + 3) but stand further from it.
  const PassabilityGrid grid = GridFromRows(kRoomEdge);
  const FootprintReach reach(grid, {2, 3}, {.radius_cells = 1.0, .reach_cells = 3.0});
  EXPECT_DOUBLE_EQ(reach.Distance({9, 3}), 7.0);
  EXPECT_EQ(reach.StandFor({9, 3}), (Cell{8, 3}));
  // A footprint-free cell is its own stand.
  EXPECT_DOUBLE_EQ(reach.Distance({5, 3}), 3.0);
  EXPECT_EQ(reach.StandFor({5, 3}), (Cell{5, 3}));
}

TEST(FootprintReach, AStandKeepingTheClearanceIsPreferred) {
  // Inflated by 2 (the clearance), columns 8-9 are blocked: (7, 3) keeps it; the distance is
  // still the shortest way.
  const PassabilityGrid grid = GridFromRows(kRoomEdge);
  const FootprintReach reach(grid, {2, 3},
                             {.radius_cells = 1.0, .reach_cells = 3.0, .clear_radius_cells = 2.0});
  EXPECT_DOUBLE_EQ(reach.Distance({9, 3}), 7.0);
  EXPECT_EQ(reach.StandFor({9, 3}), (Cell{7, 3}));
}

TEST(FootprintReach, ARobotInsideTheInflationLeavesItForTheFreeCellsNearby) {
  // (9, 3) is inflated; (8, 3) is 1 cell away, and (9, 3) is reached from it.
  const PassabilityGrid grid = GridFromRows(kRoomEdge);
  const FootprintReach reach(grid, {9, 3},
                             {.radius_cells = 1.0, .reach_cells = 3.0, .start_snap_cells = 2.0});
  EXPECT_DOUBLE_EQ(reach.Distance({8, 3}), 1.0);
  EXPECT_DOUBLE_EQ(reach.Distance({9, 3}), 2.0);
  EXPECT_DOUBLE_EQ(reach.Distance({2, 3}), 7.0);
  // Without a snap radius nothing is reachable.
  const FootprintReach stuck(grid, {9, 3}, {.radius_cells = 1.0, .reach_cells = 3.0});
  EXPECT_EQ(stuck.Distance({9, 3}), kUnreachable);
  EXPECT_FALSE(stuck.StandFor({9, 3}).has_value());
}

TEST(FootprintReach, ARobotBoxedInByTheInflationLeavesThroughTheSnapRadius) {
  // A one-cell wall at column 5; radius 1 blocks columns 4-6, and the robot at (3, 3) stands
  // free but cut off from the east (3 x 7 cells of it). GridPlanner would leave through the
  // nearest cell within its snap radius from which the goal is reached: (7, 3), 4 cells east.
  const std::vector<std::string> rows = {
      ".....#....##", ".....#....##", ".....#....##", ".....#....##",
      ".....#....##", ".....#....##", ".....#....##",
  };
  const PassabilityGrid grid = GridFromRows(rows);
  const FootprintReach boxed(grid, {3, 3}, {.radius_cells = 1.0, .reach_cells = 3.0});
  EXPECT_EQ(boxed.Distance({9, 3}), kUnreachable);
  const FootprintReach reach(grid, {3, 3},
                             {.radius_cells = 1.0, .reach_cells = 3.0, .start_snap_cells = 4.0});
  EXPECT_DOUBLE_EQ(reach.Distance({8, 3}), 5.0);  // 4 straight to (7, 3), then 1
  EXPECT_DOUBLE_EQ(reach.Distance({9, 3}), 6.0);  // frontier (9, 3), seen from (8, 3)
}

// A wall at column 7 with a one-cell gap at row 3 (from the bottom); the right room ends in
// unknown space at column 14.
const std::vector<std::string> kGap = {
    ".......#......#", ".......#......#", ".......#......#", "..............#",
    ".......#......#", ".......#......#", ".......#......#",
};

TEST(FootprintReach, AGapNarrowerThanTheRobotIsNoWayThrough) {
  const PassabilityGrid grid = GridFromRows(kGap);
  // A point robot goes through the gap to the far frontier (13, 3): 11 cells.
  EXPECT_DOUBLE_EQ(OctileDistanceField(grid, {2, 3})[grid.Index(13, 3)], 11.0);
  // Radius 1.5 closes the gap: the far frontier is out of reach, ...
  const FootprintReach reach(grid, {2, 3}, {.radius_cells = 1.5, .reach_cells = 4.0});
  EXPECT_EQ(reach.Distance({13, 3}), kUnreachable);
  EXPECT_FALSE(reach.StandFor({13, 3}).has_value());
  // ... while the cell just beyond the gap is seen from this side: (5, 3) is free (the wall's
  // inflation reaches column 6 only), 3 cells from the robot and 3 from (8, 3).
  EXPECT_DOUBLE_EQ(reach.Distance({8, 3}), 6.0);
  EXPECT_EQ(reach.StandFor({8, 3}), (Cell{5, 3}));
}

}  // namespace
}  // namespace semnav::planning
