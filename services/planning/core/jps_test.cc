#include "services/planning/core/jps.h"

#include <gtest/gtest.h>

#include <random>

#include "services/planning/core/astar.h"
#include "services/planning/core/octile.h"
#include "services/planning/core/plan_failure.h"
#include "services/planning/core/test_grids.h"

namespace semnav::planning {
namespace {

TEST(JpsPlanner, OpenGridGivesOnlyTurningPoints) {
  JpsPlanner planner;
  const PassabilityGrid grid(10, 10, 1);
  absl::StatusOr<GridPath> path = planner.Plan(grid, {0, 0}, {9, 4});
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_NEAR(path->length_cells, 5 + 4 * kSqrt2, 1e-12);
  // Diagonal run to (4,4), then straight to the goal.
  ASSERT_EQ(path->waypoints.size(), 3u);
  EXPECT_EQ(path->waypoints[1], (Cell{4, 4}));
  EXPECT_EQ(ExpandWaypoints(path->waypoints).size(), 10u);
}

TEST(JpsPlanner, NoCornerCutting) {
  JpsPlanner planner;
  const PassabilityGrid grid = GridFromRows({".@", ".."});
  absl::StatusOr<GridPath> path = planner.Plan(grid, {0, 0}, {1, 1});
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_DOUBLE_EQ(path->length_cells, 2.0);
}

TEST(JpsPlanner, ForcedNeighbourBehindWallEnd) {
  // Start left of a wall's end; the goal is tucked behind it.
  JpsPlanner planner;
  const PassabilityGrid grid = GridFromRows({
      "......",
      "@@@@..",
      "......",
  });
  // (4,0) is a jump point: moving right, (4,1) is free while (3,1) behind it is blocked.
  absl::StatusOr<GridPath> path = planner.Plan(grid, {0, 0}, {0, 2});
  ASSERT_TRUE(path.ok()) << path.status();
  // Around the wall end without cutting its corner: 4 right, 2 down, 4 left.
  EXPECT_DOUBLE_EQ(path->length_cells, 10.0);
  EXPECT_EQ(path->waypoints[1], (Cell{4, 0}));  // the forced turn
}

TEST(JpsPlanner, TypedFailuresMatchAStar) {
  JpsPlanner planner;
  const PassabilityGrid grid = GridFromRows({".@.", ".@.", ".@@"});
  EXPECT_EQ(PlanFailureOf(planner.Plan(grid, {0, 0}, {2, 0}).status()), PlanFailure::kNoPath);
  EXPECT_EQ(PlanFailureOf(planner.Plan(grid, {1, 1}, {0, 0}).status()),
            PlanFailure::kStartOccupied);
  EXPECT_EQ(PlanFailureOf(planner.Plan(grid, {0, 0}, {2, 2}).status()), PlanFailure::kGoalOccupied);
}

TEST(JpsPlanner, SameLengthAsAStarOnRandomGrids) {
  std::mt19937 rng(7);
  AStarPlanner astar;
  JpsPlanner jps;
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    PassabilityGrid grid(40, 30, 1);
    std::bernoulli_distribution blocked(0.3);
    for (uint8_t& v : grid.values()) v = blocked(rng) ? 0 : 1;
    std::uniform_int_distribution<int> x(0, 39), y(0, 29);
    const Cell s{x(rng), y(rng)};
    const Cell g{x(rng), y(rng)};
    grid.at(s) = 1;
    grid.at(g) = 1;
    absl::StatusOr<GridPath> a = astar.Plan(grid, s, g);
    absl::StatusOr<GridPath> j = jps.Plan(grid, s, g);
    ASSERT_EQ(a.ok(), j.ok()) << "trial " << trial;
    if (!a.ok()) continue;
    ++compared;
    EXPECT_NEAR(a->length_cells, j->length_cells, 1e-9) << "trial " << trial;
    // The expanded JPS path must be a connected, collision-free run of cells.
    const std::vector<Cell> cells = ExpandWaypoints(j->waypoints);
    for (size_t i = 1; i < cells.size(); ++i) {
      const Cell& p = cells[i - 1];
      ASSERT_TRUE(grid.at(cells[i]) == 1);
      const int dx = cells[i].x - p.x;
      const int dy = cells[i].y - p.y;
      ASSERT_LE(std::abs(dx), 1);
      ASSERT_LE(std::abs(dy), 1);
      if (dx != 0 && dy != 0) {
        ASSERT_TRUE(grid.at(p.x + dx, p.y) == 1 && grid.at(p.x, p.y + dy) == 1);
      }
    }
  }
  EXPECT_GT(compared, 100);
}

}  // namespace
}  // namespace semnav::planning
