#include "services/planning/core/grid_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "services/common/status/field_error.h"
#include "services/planning/core/alternative_point.h"
#include "services/planning/core/clearance_cost.h"
#include "services/planning/core/grid_path.h"
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

TEST(Inflation, DiscOffsetsHoldTheCellsWithinTheRadius) {
  EXPECT_EQ(DiscOffsets(0.0).size(), 1u);  // the cell itself
  EXPECT_EQ(DiscOffsets(1.0).size(), 5u);  // and its 4-neighbours
  EXPECT_EQ(DiscOffsets(1.5).size(), 9u);  // and the diagonals: sqrt(2) <= 1.5
  EXPECT_EQ(DiscOffsets(2.0).size(), 13u);
  EXPECT_TRUE(DiscOffsets(-1.0).empty());
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

TEST(GridPlanner, GoalToleranceStaysOnTheRobotsSideOfAWall) {
  // A desk (@) against a wall (#) with a door at the bottom row; the goal is the desk's cell by
  // the wall, 3 m tolerance. The nearest free cell, (6, 2), lies beyond the wall: 2 cells from the
  // goal but a way of about 11 round through the door. On the robot's side (1, 2) and (4, 5) lie
  // 3 cells from the goal, 1 and 5.2 cells from the start (within the 2 x 3 allowance of the
  // first); the shorter way wins the tie.
  const PassabilityGrid grid = GridFromRows({
      "..@@@#..",  // y 0
      "..@@@#..", "..@@@#..", "..@@@#..", "..@@@#..", ".....#..",
      "........",  // y 6: the door
  });
  GridPlanner planner({});
  GridPlanRequest request = RequestOn(grid, {0, 2}, {4, 2});
  request.goal_tolerance_m = 3.0;
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->goal_adjusted);
  EXPECT_EQ(result->planned_goal, (Cell{1, 2}));
  // Seen from beyond the wall the same goal is reached on that side.
  request.start = {7, 0};
  result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->planned_goal, (Cell{6, 2}));
}

TEST(GridPlanner, APaddingBeyondTheCellBudgetIsRefused) {
  // One row of 2^17 millimetre cells and a start 0.6 m above it (within max_start_outside_m):
  // the padded grid would hold 2^17 x 601 cells, more than a request grid may (2^26).
  GridPlanRequest request = RequestOn(PassabilityGrid(1 << 17, 1, 1), {5, 600}, {50, 0});
  request.resolution_m = 0.001;
  GridPlanner planner({});
  const absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(result.status().message().find("would exceed 67108864 cells"), std::string::npos)
      << result.status();
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

TEST(GridPlanner, OccupiedStartSnapsToTheNearestFreeCell) {
  // Robot radius 1 cell: the wall row 2 inflates rows 1 and 3. The robot at (3,1) stands in the
  // inflated band; the nearest free cell is (3,0), 1 cell away.
  const PassabilityGrid grid = GridFromRows({
      ".......",
      ".......",
      "@@@@@@.",
      ".......",
      ".......",
  });
  GridPlannerConfig config;
  config.start_snap_radius_m = 1.0;
  GridPlanner planner(config);
  GridPlanRequest request = RequestOn(grid, {3, 1}, {0, 0});
  request.robot_radius_m = 1.0;
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->start_adjusted);
  EXPECT_EQ(result->planned_start, (Cell{3, 0}));
  ASSERT_GE(result->path.waypoints.size(), 2u);
  EXPECT_EQ(result->path.waypoints.front(), (Cell{3, 1}));  // begins where the robot stands
  EXPECT_EQ(result->path.waypoints[1], (Cell{3, 0}));
  EXPECT_DOUBLE_EQ(result->path.length_cells, 1.0 + 3.0);

  // A snap radius below one cell leaves the typed failure.
  config.start_snap_radius_m = 0.9;
  GridPlanner strict(config);
  EXPECT_EQ(PlanFailureOf(strict.Plan(request).status()), PlanFailure::kStartOccupied);
}

TEST(GridPlanner, StartBoxedInByTheInflationLeavesItsIsland) {
  // Robot radius 1 cell. The robot at (1,2) stands on a free island: the inflated counter
  // (row 0, columns 0-3) and wall cell (3,3) cut it off from the room on the right.
  const PassabilityGrid grid = GridFromRows({
      "@@@@........",
      "............",
      "............",
      "...@........",
      "@@@@@@@@@@@@",
  });
  GridPlanRequest request = RequestOn(grid, {1, 2}, {10, 2});
  request.robot_radius_m = 1.0;
  GridPlannerConfig config;
  config.start_snap_radius_m = 0.0;
  EXPECT_EQ(PlanFailureOf(GridPlanner(config).Plan(request).status()), PlanFailure::kNoPath);
  config.start_snap_radius_m = 2.9;  // below 3 cells: still no way out
  EXPECT_EQ(PlanFailureOf(GridPlanner(config).Plan(request).status()), PlanFailure::kNoPath);
  config.start_snap_radius_m = 3.0;
  absl::StatusOr<GridPlanResult> result = GridPlanner(config).Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->start_adjusted);
  EXPECT_EQ(result->path.waypoints.front(), (Cell{1, 2}));
  // The island is {(0,2), (1,2), (2,2)} ((3,2) is inflated by (3,3)); the nearest cell the goal
  // is reached from is (4,2), 3 cells east ((4,1) is sqrt(10) away), both sqrt(2) from (3,3).
  EXPECT_EQ(result->planned_start, (Cell{4, 2}));
}

TEST(GridPlanner, StartJustOutsideTheGridPadsIt) {
  PassabilityGrid grid(5, 5, 1);
  GridPlannerConfig config;
  config.max_start_outside_m = 1.0;
  GridPlanner planner(config);
  GridPlanRequest request = RequestOn(grid, {-1, 2}, {4, 2});
  request.resolution_m = 0.5;  // 0.5 m outside
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->grid_padded);
  EXPECT_FALSE(result->start_adjusted);
  EXPECT_EQ(result->path.waypoints.front(), (Cell{-1, 2}));
  EXPECT_EQ(result->path.waypoints.back(), (Cell{4, 2}));
  EXPECT_EQ(result->planned_goal, (Cell{4, 2}));
  EXPECT_DOUBLE_EQ(result->path.length_cells, 5.0);

  // Beyond and above the top-right corner too.
  request.start = {6, 6};  // sqrt(2) x 2 cells x 0.5 m = 1.41 m > 1 m
  absl::Status far = planner.Plan(request).status();
  EXPECT_EQ(far.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(far), "start");
  request.start = {5, 5};  // 0.71 m
  result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->path.waypoints.front(), (Cell{5, 5}));

  // A goal just outside (1 m at 0.5 m cells) goes to the nearest edge cell; farther, an error
  // naming the goal.
  request.start = {0, 2};
  request.goal = {6, 2};
  result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->goal_adjusted);
  EXPECT_EQ(result->planned_goal, (Cell{4, 2}));
  EXPECT_NE(result->adjustment_reason.find("outside the grid"), std::string::npos);
  request.goal = {7, 2};
  EXPECT_EQ(ErrorField(planner.Plan(request).status()), "goal");
}

TEST(GridPlanner, GoalBeyondTheGridPadsItWhenOutsideIsFree) {
  // An exploration goal 3 cells past the right edge of a 5 x 5 map whose unknown counts as free.
  const PassabilityGrid grid(5, 5, 1);
  GridPlannerConfig config;
  config.max_free_goal_outside_m = 4.0;
  GridPlanner planner(config);
  GridPlanRequest request = RequestOn(grid, {0, 2}, {7, 2});
  request.outside_is_free = true;
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->grid_padded);
  EXPECT_FALSE(result->goal_adjusted);
  EXPECT_EQ(result->planned_goal, (Cell{7, 2}));
  EXPECT_EQ(result->path.waypoints.back(), (Cell{7, 2}));
  EXPECT_DOUBLE_EQ(result->path.length_cells, 7.0);
  // Farther than the padding budget: as before, an error naming the goal.
  request.goal = {10, 2};
  EXPECT_EQ(ErrorField(planner.Plan(request).status()), "goal");
  // Outside not free: the edge cell, as before.
  request.outside_is_free = false;
  request.goal = {5, 2};
  result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->planned_goal, (Cell{4, 2}));
}

TEST(GridPlanner, ClearanceKeepsTheCorridorPathCentred) {
  // A corridor of 7 free rows (1..7) between walls; start and goal next to the lower wall.
  std::vector<std::string> rows(9, std::string(40, '.'));
  rows[0] = rows[8] = std::string(40, '@');
  const PassabilityGrid grid = GridFromRows(rows);
  GridPlanRequest request = RequestOn(grid, {1, 1}, {38, 1});
  request.resolution_m = 0.1;
  request.keep_clearance = true;
  GridPlannerConfig config;
  config.clearance = {.clearance_m = 0.4, .cost_scaling_per_m = 3.0, .cost_penalty = 2.0};
  absl::StatusOr<GridPlanResult> centred = GridPlanner(config).Plan(request);
  ASSERT_TRUE(centred.ok()) << centred.status();
  const std::vector<Cell> cells = CellsAlongLegs(centred->path.waypoints);
  for (const Cell& c : cells) {
    if (c.x == 20) {
      EXPECT_EQ(c.y, 4);  // the middle row, 4 cells from both walls
    }
  }
  // Straight legs: up to the middle row, along it, down to the goal (not a staircase of cells).
  EXPECT_LE(centred->path.waypoints.size(), 4u);
  // Not asked for (a metric's shortest path), or off in the config: the path runs along the wall.
  request.keep_clearance = false;
  absl::StatusOr<GridPlanResult> hugging = GridPlanner(config).Plan(request);
  ASSERT_TRUE(hugging.ok()) << hugging.status();
  EXPECT_DOUBLE_EQ(hugging->path.length_cells, 37.0);
  EXPECT_GT(centred->path.length_cells, 37.0);
  request.keep_clearance = true;
  config.clearance.clearance_m = 0.0;
  hugging = GridPlanner(config).Plan(request);
  ASSERT_TRUE(hugging.ok()) << hugging.status();
  EXPECT_DOUBLE_EQ(hugging->path.length_cells, 37.0);
}

TEST(GridPlanner, GapNarrowerThanTheRobotIsRefusedWithClearanceOn) {
  // A 3-cell gap (0.3 m) in a wall; a 0.2 m robot needs 0.4 m (inflation blocks the whole gap).
  std::vector<std::string> rows(11, std::string(11, '.'));
  rows[5] = "@@@@...@@@@";
  const PassabilityGrid grid = GridFromRows(rows);
  GridPlanRequest request = RequestOn(grid, {5, 0}, {5, 10});
  request.resolution_m = 0.1;
  request.robot_radius_m = 0.2;
  request.keep_clearance = true;
  GridPlanner planner({});
  EXPECT_EQ(PlanFailureOf(planner.Plan(request).status()), PlanFailure::kNoPath);
  // A 0.1 m robot passes, through the middle cell of the gap.
  request.robot_radius_m = 0.1;
  absl::StatusOr<GridPlanResult> result = planner.Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  bool through_middle = false;
  for (const Cell& c : CellsAlongLegs(result->path.waypoints)) {
    if (c.y == 5) through_middle = c.x == 5;
  }
  EXPECT_TRUE(through_middle);
}

// A footprint prepared once gives each call the same path as one prepared in the call; one that
// does not fit the request (another radius) is not used.
TEST(GridPlanner, APreparedFootprintPlansAsTheCallsOwnAndOneThatDoesNotFitIsIgnored) {
  std::vector<std::string> rows(11, std::string(11, '.'));
  rows[5] = "@@@@...@@@@";
  const PassabilityGrid grid = GridFromRows(rows);
  GridPlanRequest request = RequestOn(grid, {5, 0}, {5, 10});
  request.resolution_m = 0.1;
  request.robot_radius_m = 0.1;
  request.keep_clearance = true;
  GridPlannerConfig config;
  config.clearance = {.clearance_m = 0.4, .cost_scaling_per_m = 3.0, .cost_penalty = 2.0};
  GridPlanner planner(config);
  const absl::StatusOr<GridPlanResult> own = planner.Plan(request);
  ASSERT_TRUE(own.ok()) << own.status();

  request.prepared = std::make_shared<const PreparedFootprint>(
      planner.Prepare(grid, request.resolution_m, request.robot_radius_m, true));
  EXPECT_EQ(request.prepared->inflated.at(4, 5), 0);  // the wall's end grown by one cell
  EXPECT_EQ(request.prepared->clearance_cost.size(), 121u);
  for (int call = 0; call < 2; ++call) {
    const absl::StatusOr<GridPlanResult> reused = planner.Plan(request);
    ASSERT_TRUE(reused.ok()) << reused.status();
    EXPECT_EQ(reused->path.waypoints, own->path.waypoints);
    EXPECT_DOUBLE_EQ(reused->path.length_cells, own->path.length_cells);
  }
  // Prepared for a 0.2 m robot, which the gap refuses: this 0.1 m request still passes.
  request.prepared = std::make_shared<const PreparedFootprint>(
      planner.Prepare(grid, request.resolution_m, 0.2, true));
  const absl::StatusOr<GridPlanResult> other = planner.Plan(request);
  ASSERT_TRUE(other.ok()) << other.status();
  EXPECT_EQ(other->path.waypoints, own->path.waypoints);
}

TEST(ClearanceCost, DecaysExponentiallyWithDistance) {
  const PassabilityGrid grid = GridFromRows({"@......"});
  const std::vector<float> cost = ClearanceCost(
      grid, 0.1, {.clearance_m = 0.3, .cost_scaling_per_m = 3.0, .cost_penalty = 2.0});
  ASSERT_EQ(cost.size(), 7u);
  EXPECT_FLOAT_EQ(cost[0], 0.0f);                    // blocked
  EXPECT_FLOAT_EQ(cost[1], 2.0f);                    // next to it
  EXPECT_NEAR(cost[2], 2.0 * std::exp(-0.3), 1e-6);  // 0.1 m further
  EXPECT_NEAR(cost[3], 2.0 * std::exp(-0.6), 1e-6);
  EXPECT_FLOAT_EQ(cost[4], 0.0f);  // 0.4 m: beyond clearance_m
  EXPECT_TRUE(ClearanceCost(PassabilityGrid(4, 4, 1), 0.1, {}).empty());  // nothing blocked
}

}  // namespace
}  // namespace semnav::planning
