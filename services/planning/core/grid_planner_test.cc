#include "services/planning/core/grid_planner.h"

#include <gtest/gtest.h>

#include "services/planning/core/alternative_point.h"
#include "services/planning/core/inflation.h"
#include "services/planning/core/plan_failure.h"
#include "services/planning/core/test_grids.h"

namespace semnav::planning {
namespace {

GridPlanRequest RequestOn(const PassabilityGrid& grid, Cell start, Cell goal) {
  GridPlanRequest request;
  request.free = grid;
  request.resolution_m = 1.0;
  request.start = start;
  request.goal = goal;
  return request;
}

TEST(Inflation, BlocksCellsWithinTheRadius) {
  PassabilityGrid grid(7, 7, 1);
  grid.at(3, 3) = 0;
  const PassabilityGrid inflated = InflateObstacles(grid, 1.5);
  EXPECT_EQ(inflated.at(4, 4), 0);  // diagonal neighbour: sqrt(2) <= 1.5
  EXPECT_EQ(inflated.at(5, 3), 1);  // 2 cells away
  EXPECT_EQ(inflated.at(3, 1), 1);
  int blocked = 0;
  for (uint8_t v : inflated.values()) blocked += v == 0;
  EXPECT_EQ(blocked, 9);
}

TEST(GridPlanner, FootprintInflationClosesANarrowGap) {
  // A one-cell door in a wall; a 1-cell-radius robot cannot pass it.
  const PassabilityGrid grid = GridFromRows({
      ".......",
      ".......",
      "@@@.@@@",
      ".......",
      ".......",
  });
  GridPlanner planner({});
  GridPlanRequest request = RequestOn(grid, {3, 0}, {3, 4});
  absl::StatusOr<GridPlanResult> point_robot = planner.Plan(request);
  ASSERT_TRUE(point_robot.ok()) << point_robot.status();
  EXPECT_DOUBLE_EQ(point_robot->path.length_cells, 4.0);
  request.robot_radius_m = 1.0;
  EXPECT_EQ(PlanFailureOf(planner.Plan(request).status()), PlanFailure::kNoPath);
  request.start = {2, 1};  // 1 m from the wall cell (2,2): inflated
  EXPECT_EQ(PlanFailureOf(planner.Plan(request).status()), PlanFailure::kStartOccupied);
}

TEST(GridPlanner, AlternativePointOnTheSightingLine) {
  // A TV in a wall: the goal cell (3,0) is blocked; the robot first saw it
  // from (3,4). The nearest free reachable line cell is (3,1).
  const PassabilityGrid grid = GridFromRows({
      "@@@@@@",
      "......",
      "......",
      "......",
      "......",
  });
  GridPlanner planner({});
  GridPlanRequest request = RequestOn(grid, {0, 4}, {3, 0});
  EXPECT_EQ(PlanFailureOf(planner.Plan(request).status()), PlanFailure::kGoalOccupied);
  request.first_sighting = Cell{3, 4};
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->alternative_used);
  EXPECT_EQ(result->planned_goal, (Cell{3, 1}));
  EXPECT_NE(result->adjustment_reason.find("inside an obstacle"), std::string::npos);
}

TEST(GridPlanner, AlternativePointSkipsUnreachableLineCells) {
  // A plant on a table: the goal (4,2) is free but boxed in by the table.
  // Line from the sighting (0,2): (1,2) (2,2) blocked... (3,2) is table.
  const PassabilityGrid grid = GridFromRows({
      ".......",
      "...@@@.",
      "...@.@.",
      "...@@@.",
      ".......",
  });
  GridPlanner planner({});
  GridPlanRequest request = RequestOn(grid, {0, 0}, {4, 2});
  EXPECT_EQ(PlanFailureOf(planner.Plan(request).status()), PlanFailure::kNoPath);
  request.first_sighting = Cell{0, 2};
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->planned_goal, (Cell{2, 2}));
  EXPECT_NE(result->adjustment_reason.find("enclosed"), std::string::npos);
}

TEST(GridPlanner, GoalToleranceMovesAnOccupiedGoal) {
  const PassabilityGrid grid = GridFromRows({"..@@@", "..@@@", "....."});
  GridPlanner planner({});
  GridPlanRequest request = RequestOn(grid, {0, 1}, {3, 1});
  request.goal_tolerance_m = 0.9;
  EXPECT_EQ(PlanFailureOf(planner.Plan(request).status()), PlanFailure::kGoalOccupied);
  request.goal_tolerance_m = 1.0;
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->goal_adjusted);
  EXPECT_FALSE(result->alternative_used);
  EXPECT_EQ(result->planned_goal, (Cell{3, 2}));  // the only free cell 1 m away
}

TEST(GridPlanner, ZeroProbabilityCellsFirstThenLowProbability) {
  PassabilityGrid grid(5, 3, 1);
  CellGrid<uint8_t> probability(5, 3, 0);
  // A column of 30 % cells across the whole map separates start and goal.
  for (int y = 0; y < 3; ++y) probability.at(2, y) = 30;
  GridPlanner planner({});
  GridPlanRequest request = RequestOn(grid, {0, 1}, {4, 1});
  request.obstacle_probability = probability;
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->low_probability_cells_used);
  EXPECT_DOUBLE_EQ(result->path.length_cells, 4.0);

  // Leave a zero-probability gap: the detour over it is preferred.
  probability.at(2, 0) = 0;
  request.obstacle_probability = probability;
  result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->low_probability_cells_used);
  EXPECT_GT(result->path.length_cells, 4.0);

  // Above the low-probability limit (50 %) nothing helps.
  for (int y = 0; y < 3; ++y) probability.at(2, y) = 80;
  request.obstacle_probability = probability;
  EXPECT_EQ(PlanFailureOf(planner.Plan(request).status()), PlanFailure::kNoPath);
}

}  // namespace
}  // namespace semnav::planning
