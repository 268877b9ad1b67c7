#include "services/planning/core/look_goal.h"

#include <gtest/gtest.h>

namespace semnav::planning {
namespace {

// 20 x 10 cells of 0.5 m from (0, 0), all explored and free. A robot at x = 1.25 stands in
// column 2; column k's centre is 0.5 k - 1 m along a line east from it.
ExplorationGrid OpenGrid() {
  ExplorationGrid grid;
  grid.resolution_m = 0.5;
  grid.explored = CellGrid<uint8_t>(20, 10, 1);
  grid.free = PassabilityGrid(20, 10, 1);
  return grid;
}

// A wall the map knows in column 10 (x in [5, 5.5) m, 4 m along from x = 1.25).
void AddWall(ExplorationGrid& grid) {
  for (int y = 0; y < 10; ++y) grid.free.at(10, y) = 0;
}

// Columns from `first` on never seen (a building's inside behind its wall).
void Unseen(ExplorationGrid& grid, int first) {
  for (int y = 0; y < 10; ++y) {
    for (int x = first; x < 20; ++x) grid.explored.at(x, y) = grid.free.at(x, y) = 0;
  }
}

constexpr LookGoalConfig kConfig{.distance_m = 3.0, .clearance_m = 1.0};

TEST(LookGoalTest, InTheOpenTheGoalIsTheDistanceShortOfTheSighting) {
  // 8 m from (1.25, 1.25) to (9.25, 1.25): 3 m short is x = 6.25.
  const Point2 goal = LookGoal(OpenGrid(), {1.25, 1.25}, {9.25, 1.25}, kConfig);
  EXPECT_NEAR(goal.x, 6.25, 1e-9);
  EXPECT_NEAR(goal.y, 1.25, 1e-9);
  // Diagonal: (1, 1) to (7, 9) is 10 m long; 7 m along it is (1 + 4.2, 1 + 5.6).
  const Point2 diagonal = LookGoal(OpenGrid(), {1.0, 1.0}, {7.0, 9.0}, kConfig);
  EXPECT_NEAR(diagonal.x, 5.2, 1e-9);
  EXPECT_NEAR(diagonal.y, 6.6, 1e-9);
}

TEST(LookGoalTest, ALookIntoABuildingsUnseenInsideStopsOutsideItsWall) {
  // The straight look (x = 6.25, 5 m along) lies in unseen space behind the wall (4 m along).
  // Seen free cells at least 1 m + half a diagonal (0.354 m) from the wall end 2.646 m along:
  // column 7's centre, 2.5 m along, x = 3.75.
  ExplorationGrid grid = OpenGrid();
  AddWall(grid);
  Unseen(grid, 11);
  const Point2 goal = LookGoal(grid, {1.25, 1.25}, {9.25, 1.25}, kConfig);
  EXPECT_NEAR(goal.x, 3.75, 1e-9);
  EXPECT_NEAR(goal.y, 1.25, 1e-9);
}

TEST(LookGoalTest, AWallTheMapSawPastIsFlownRound) {
  // A low bridge or a tree: the map saw the free space beyond it. The straight look (5 m along)
  // is within 1.354 m of the wall (4 m along), so the seen free cell nearest it and clear of the
  // wall is column 13, 5.5 m along: x = 6.75, beyond the wall (the path planner goes round).
  ExplorationGrid grid = OpenGrid();
  AddWall(grid);
  EXPECT_NEAR(LookGoal(grid, {1.25, 1.25}, {9.25, 1.25}, kConfig).x, 6.75, 1e-9);
  // 8.5 m to the sighting: the straight look, 5.5 m along, is seen free and clear of the wall.
  EXPECT_NEAR(LookGoal(grid, {1.25, 1.25}, {9.75, 1.25}, kConfig).x, 6.75, 1e-9);
}

TEST(LookGoalTest, AWallTheMapHasNotSeenDoesNotCountAndUnseenSpaceAloneNeither) {
  ExplorationGrid grid = OpenGrid();
  for (int y = 0; y < 10; ++y) grid.explored.at(10, y) = grid.free.at(10, y) = 0;
  EXPECT_NEAR(LookGoal(grid, {1.25, 1.25}, {9.25, 1.25}, kConfig).x, 6.25, 1e-9);
  // All unseen beyond column 6: no wall the map knows, the straight look stands.
  Unseen(grid, 6);
  EXPECT_NEAR(LookGoal(grid, {1.25, 1.25}, {9.25, 1.25}, kConfig).x, 6.25, 1e-9);
}

TEST(LookGoalTest, ARobotThatCloseOrFacingTheWallLooksFromWhereItStands) {
  ExplorationGrid grid = OpenGrid();
  // 2 m from the sighting: within the 3 m.
  Point2 goal = LookGoal(grid, {1.25, 1.25}, {3.25, 1.25}, kConfig);
  EXPECT_DOUBLE_EQ(goal.x, 1.25);
  EXPECT_DOUBLE_EQ(goal.y, 1.25);
  // The wall 1 m ahead with the unseen inside behind it: column 9, the only seen cell in front,
  // is 0.5 m from the wall, within the clearance.
  AddWall(grid);
  Unseen(grid, 11);
  goal = LookGoal(grid, {4.25, 1.25}, {9.75, 1.25}, kConfig);
  EXPECT_DOUBLE_EQ(goal.x, 4.25);
  EXPECT_DOUBLE_EQ(goal.y, 1.25);
}

TEST(LookGoalTest, ASightingFarOffTheGridIsWalkedOnlyToTheGridsEdge) {
  // 100 km east: the line leaves the 10 m grid at x = 10; nothing known blocks the way, so the
  // goal lies 3 m short of the sighting.
  ExplorationGrid grid = OpenGrid();
  const Point2 goal = LookGoal(grid, {1.25, 1.25}, {1e5, 1.25}, kConfig);
  EXPECT_NEAR(goal.x, 1e5 - 3.0, 1e-6);
  EXPECT_NEAR(goal.y, 1.25, 1e-9);
  // Behind a wall with an unseen inside, the straight look (off the grid) is unseen: column 7.
  AddWall(grid);
  Unseen(grid, 11);
  EXPECT_NEAR(LookGoal(grid, {1.25, 1.25}, {1e5, 1.25}, kConfig).x, 3.75, 1e-9);
}

}  // namespace
}  // namespace semnav::planning
