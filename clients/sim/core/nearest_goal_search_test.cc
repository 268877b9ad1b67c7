#include "clients/sim/core/nearest_goal_search.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::sim {
namespace {

GroundTruthGrid Grid(int width, int height) {
  GroundTruthGrid grid;
  grid.resolution = 1.0;
  grid.width = width;
  grid.height = height;
  grid.cells.assign(static_cast<size_t>(width) * height, 0);
  return grid;
}

TEST(SimNearestGoalTest, OpenGridStopsAtTheNearestGoalCell) {
  const GroundTruthGrid grid = Grid(10, 10);
  // Goal cells: centre x > 8. From (0.5, 0.5) the nearest is (8.5, 0.5), 8 straight steps.
  const auto goal =
      NearestReachableGoal(grid, {0.5, 0.5}, [](const Eigen::Vector2d& p) { return p.x() > 8; });
  ASSERT_TRUE(goal.has_value());
  EXPECT_DOUBLE_EQ(goal->goal.x(), 8.5);
  EXPECT_DOUBLE_EQ(goal->goal.y(), 0.5);
  EXPECT_DOUBLE_EQ(goal->length_m, 8.0);
}

TEST(SimNearestGoalTest, WallsAreWalkedRoundWithoutCuttingCorners) {
  // 5 x 3 cells, row y = 1 blocked for x = 0..3; start (0, 0), goal cell (0, 2). Round the wall's
  // end: (0,0) -> (4,0) is 4, up to (4,2) is 2 (the diagonals (3,0)->(4,1) and (4,1)->(3,2)
  // would cut the corner of (3,1)), back to (0,2) is 4: 10 cells. Straight through would be 2.
  GroundTruthGrid grid = Grid(5, 3);
  for (int x = 0; x <= 3; ++x) grid.cells[1 * 5 + x] = 100;
  const auto goal = NearestReachableGoal(
      grid, {0.5, 0.5}, [](const Eigen::Vector2d& p) { return p.x() < 1 && p.y() > 2; });
  ASSERT_TRUE(goal.has_value());
  EXPECT_DOUBLE_EQ(goal->length_m, 10.0);
  // The path: start cell to goal cell, in steps to neighbours, as long as length_m, never on the
  // wall.
  ASSERT_GE(goal->path.size(), 2u);
  EXPECT_EQ(goal->path.front(), Eigen::Vector2d(0.5, 0.5));
  EXPECT_EQ(goal->path.back(), goal->goal);
  double walked = 0.0;
  for (size_t i = 1; i < goal->path.size(); ++i) {
    const double step = (goal->path[i] - goal->path[i - 1]).norm();
    EXPECT_LE(step, std::sqrt(2.0) + 1e-9);
    walked += step;
    EXPECT_FALSE(goal->path[i].y() == 1.5 && goal->path[i].x() < 4.0) << goal->path[i].transpose();
  }
  EXPECT_NEAR(walked, goal->length_m, 1e-9);
  // A diagonal step costs sqrt(2): (0,0) -> (1,1) on an open grid.
  const auto diagonal = NearestReachableGoal(Grid(3, 3), {0.5, 0.5}, [](const Eigen::Vector2d& p) {
    return p.x() > 1 && p.x() < 2 && p.y() > 1 && p.y() < 2;
  });
  ASSERT_TRUE(diagonal.has_value());
  EXPECT_DOUBLE_EQ(diagonal->length_m, std::sqrt(2.0));
}

TEST(SimNearestGoalTest, UnreachableOccupiedOrOutsideStartGiveNothing) {
  GroundTruthGrid grid = Grid(5, 3);
  for (int x = 0; x < 5; ++x) grid.cells[1 * 5 + x] = 100;  // a full wall
  auto upper = [](const Eigen::Vector2d& p) { return p.y() > 2; };
  EXPECT_FALSE(NearestReachableGoal(grid, {0.5, 0.5}, upper).has_value());
  EXPECT_FALSE(NearestReachableGoal(grid, {0.5, 1.5}, upper).has_value());   // start occupied
  EXPECT_FALSE(NearestReachableGoal(grid, {-1.0, 0.5}, upper).has_value());  // outside
}

}  // namespace
}  // namespace semnav::sim
