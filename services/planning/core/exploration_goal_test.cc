#include "services/planning/core/exploration_goal.h"

#include <gtest/gtest.h>

namespace semnav::planning {
namespace {

// A 3 x 2 grid of 0.5 m cells at (10, 20): row 0 explored and free, row 1 unexplored.
ExplorationGrid SmallGrid() {
  ExplorationGrid grid;
  grid.resolution_m = 0.5;
  grid.origin_x = 10.0;
  grid.origin_y = 20.0;
  grid.explored = CellGrid<uint8_t>(3, 2, 0);
  grid.free = PassabilityGrid(3, 2, 0);
  for (int x = 0; x < 3; ++x) grid.explored.at(x, 0) = grid.free.at(x, 0) = 1;
  return grid;
}

TEST(TakeInRobotTest, ARobotInsideTheGridChangesNothing) {
  ExplorationGrid grid = SmallGrid();
  ExplorationQuery query;
  query.robot = {2, 1};
  absl::StatusOr<Padding> pad = TakeInRobot(grid, query, 1.0);
  ASSERT_TRUE(pad.ok()) << pad.status();
  EXPECT_FALSE(pad->any());
  EXPECT_EQ(grid.free.width(), 3);
  EXPECT_EQ(query.robot, (Cell{2, 1}));
  EXPECT_DOUBLE_EQ(grid.origin_x, 10.0);
}

TEST(TakeInRobotTest, ARobotJustBeyondTheEdgeGrowsTheGridWithAPassableUnexploredStrip) {
  // Two cells (1 m) left of column 0, in row 0: the grid grows by two columns on the left.
  ExplorationGrid grid = SmallGrid();
  ExplorationQuery query;
  query.robot = {-2, 0};
  absl::StatusOr<Padding> pad = TakeInRobot(grid, query, 1.0);
  ASSERT_TRUE(pad.ok()) << pad.status();
  EXPECT_EQ(pad->left, 2);
  EXPECT_EQ(pad->right + pad->bottom + pad->top, 0);
  ASSERT_EQ(grid.free.width(), 5);
  ASSERT_EQ(grid.explored.width(), 5);
  EXPECT_EQ(grid.free.height(), 2);
  EXPECT_EQ(query.robot, (Cell{0, 0}));
  EXPECT_DOUBLE_EQ(grid.origin_x, 9.0);  // the robot's cell centre stays at 9.25
  EXPECT_DOUBLE_EQ(grid.origin_y, 20.0);
  EXPECT_DOUBLE_EQ(grid.CentreOf(query.robot).x, 9.25);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) {
      EXPECT_EQ(grid.free.at(x, y), 1) << x << "," << y;      // the robot stands in it
      EXPECT_EQ(grid.explored.at(x, y), 0) << x << "," << y;  // unseen
    }
  }
  // The old cells moved with their values: explored free row 0, unexplored row 1.
  EXPECT_EQ(grid.explored.at(2, 0), 1);
  EXPECT_EQ(grid.free.at(4, 0), 1);
  EXPECT_EQ(grid.explored.at(2, 1), 0);
  EXPECT_EQ(grid.free.at(2, 1), 0);
}

TEST(TakeInRobotTest, ARobotFartherOutIsRefusedByName) {
  // Diagonally beyond the top-right corner by (2, 2) cells: 1.41 m > 1 m.
  ExplorationGrid grid = SmallGrid();
  ExplorationQuery query;
  query.robot = {4, 3};
  absl::StatusOr<Padding> pad = TakeInRobot(grid, query, 1.0);
  ASSERT_FALSE(pad.ok());
  EXPECT_EQ(pad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(pad.status().message().find("robot"), std::string::npos);
  EXPECT_EQ(grid.free.width(), 3);  // unchanged
  EXPECT_EQ(query.robot, (Cell{4, 3}));
  // Within 1.5 m the same robot is taken in: two columns on the right, two rows on top.
  pad = TakeInRobot(grid, query, 1.5);
  ASSERT_TRUE(pad.ok()) << pad.status();
  EXPECT_EQ(pad->right, 2);
  EXPECT_EQ(pad->top, 2);
  EXPECT_EQ(grid.free.width(), 5);
  EXPECT_EQ(grid.free.height(), 4);
  EXPECT_EQ(query.robot, (Cell{4, 3}));  // padding right and top keeps the indices
}

TEST(TakeInRobotTest, APaddingBeyondTheCellBudgetIsRefused) {
  // One row of 2^17 millimetre cells and a robot 0.6 m (600 cells) above it: 2^17 x 601 cells
  // exceed the 2^26 a request grid may hold, so nothing is allocated.
  ExplorationGrid grid;
  grid.resolution_m = 0.001;
  grid.explored = CellGrid<uint8_t>(1 << 17, 1, 1);
  grid.free = PassabilityGrid(1 << 17, 1, 1);
  ExplorationQuery query;
  query.robot = {5, 600};
  absl::StatusOr<Padding> pad = TakeInRobot(grid, query, 1.0);
  ASSERT_FALSE(pad.ok());
  EXPECT_EQ(pad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(pad.status().message().find("would exceed 67108864 cells"), std::string::npos)
      << pad.status();
  EXPECT_EQ(grid.free.height(), 1);
}

TEST(TakeInRobotTest, ARobotJustOutsideGetsAFrontierGoal) {
  // Before, the robot outside the grid had no goal at all. Taken in, the nearest frontier is the
  // unexplored row's edge: row 0 cells border row 1, and the strip's column borders column 0.
  ExplorationGrid grid = SmallGrid();
  ExplorationQuery query;
  query.robot = {-1, 0};
  query.min_frontier_cells = 1;
  ASSERT_TRUE(TakeInRobot(grid, query, 1.0).ok());
  absl::StatusOr<ExplorationChoice> choice = SelectExplorationGoal(
      grid, query, ExplorationStrategy::kNearestFrontier, ExplorationGoalConfig{});
  ASSERT_TRUE(choice.ok()) << choice.status();
  EXPECT_EQ(choice->goal, (Cell{1, 0}));  // the old (0, 0), one cell from the robot
  EXPECT_DOUBLE_EQ(choice->score, 0.5);
}

}  // namespace
}  // namespace semnav::planning
