#include "services/planning/core/astar.h"

#include <gtest/gtest.h>

#include "services/planning/core/octile.h"
#include "services/planning/core/plan_failure.h"
#include "services/planning/core/test_grids.h"

namespace semnav::planning {
namespace {

TEST(AStarPlanner, StraightAndDiagonalOnEmptyGrid) {
  AStarPlanner planner;
  const PassabilityGrid grid = GridFromRows({"....", "....", "...."});
  absl::StatusOr<GridPath> path = planner.Plan(grid, {0, 0}, {3, 2});
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_NEAR(path->length_cells, 1 + 2 * kSqrt2, 1e-12);
  EXPECT_EQ(path->waypoints.front(), (Cell{0, 0}));
  EXPECT_EQ(path->waypoints.back(), (Cell{3, 2}));
  EXPECT_EQ(path->waypoints.size(), 4u);  // every cell of a 3-step path
}

TEST(AStarPlanner, NoCornerCuttingAroundABlock) {
  // Going (0,0) -> (1,1) diagonally would cut the corner of the block at (1,0).
  AStarPlanner planner;
  const PassabilityGrid grid = GridFromRows({".@", ".."});
  absl::StatusOr<GridPath> path = planner.Plan(grid, {0, 0}, {1, 1});
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_DOUBLE_EQ(path->length_cells, 2.0);
}

TEST(AStarPlanner, DetourAroundWall) {
  AStarPlanner planner;
  const PassabilityGrid grid = GridFromRows({
      ".....",
      ".@@@.",
      ".....",
  });
  // (0,1) -> (4,1): no diagonal may touch the wall's corners, so the path is
  // up 1, across 4, down 1.
  absl::StatusOr<GridPath> path = planner.Plan(grid, {0, 1}, {4, 1});
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_DOUBLE_EQ(path->length_cells, 6.0);
}

TEST(AStarPlanner, TypedFailures) {
  AStarPlanner planner;
  const PassabilityGrid grid = GridFromRows({".@.", ".@.", ".@@"});
  absl::StatusOr<GridPath> no_path = planner.Plan(grid, {0, 0}, {2, 0});
  EXPECT_EQ(no_path.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(PlanFailureOf(no_path.status()), PlanFailure::kNoPath);

  absl::StatusOr<GridPath> start_blocked = planner.Plan(grid, {1, 0}, {0, 0});
  EXPECT_EQ(start_blocked.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(PlanFailureOf(start_blocked.status()), PlanFailure::kStartOccupied);

  absl::StatusOr<GridPath> goal_blocked = planner.Plan(grid, {0, 0}, {2, 2});
  EXPECT_EQ(PlanFailureOf(goal_blocked.status()), PlanFailure::kGoalOccupied);

  absl::StatusOr<GridPath> outside = planner.Plan(grid, {0, 0}, {3, 0});
  EXPECT_EQ(outside.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(outside.status().message().find("goal"), absl::string_view::npos);
  EXPECT_FALSE(PlanFailureOf(outside.status()).has_value());
}

TEST(AStarPlanner, CancelledAndTimedOut) {
  AStarPlanner planner;
  // Straight-line queries expand one cell per step: 600 expansions here.
  const PassabilityGrid grid(600, 600, 1);
  int polls = 0;
  SearchLimits cancel_limits;
  cancel_limits.is_cancelled = [&polls] { return ++polls >= 2; };  // cancel on the 2nd poll
  absl::StatusOr<GridPath> cancelled_path = planner.Plan(grid, {0, 0}, {599, 599}, cancel_limits);
  EXPECT_EQ(cancelled_path.status().code(), absl::StatusCode::kCancelled);
  EXPECT_EQ(PlanFailureOf(cancelled_path.status()), PlanFailure::kCancelled);
  EXPECT_EQ(polls, 2);  // polled every kLimitCheckInterval expansions, then stopped

  SearchLimits past_deadline;
  past_deadline.deadline = absl::Now() - absl::Seconds(1);
  absl::StatusOr<GridPath> timed_out = planner.Plan(grid, {0, 0}, {599, 0}, past_deadline);
  EXPECT_EQ(timed_out.status().code(), absl::StatusCode::kDeadlineExceeded);
  EXPECT_EQ(PlanFailureOf(timed_out.status()), PlanFailure::kTimeout);
}

}  // namespace
}  // namespace semnav::planning
