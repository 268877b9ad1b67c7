#include "services/planning/core/jump_astar.h"

#include <gtest/gtest.h>

#include <random>

#include "services/planning/core/octile.h"
#include "services/planning/core/plan_failure.h"
#include "services/planning/core/random_layered_map.h"

namespace semnav::planning {
namespace {

JumpAStarOptions MetreCells(double beta) {
  JumpAStarOptions options;
  options.resolution_m = 1.0;
  options.beta = beta;
  return options;
}

TEST(JumpAStar, FliesOverTheOnlyObstacleInACorridor) {
  LayeredGrid grid(10, 1, 0);
  grid.at(5, 0) = 40;
  JumpAStarPlanner planner;
  JumpAStarOptions options;  // 5 cm cells
  absl::StatusOr<MultiModalPath> path = planner.Plan(grid, {0, 0}, {9, 0}, options);
  ASSERT_TRUE(path.ok()) << path.status();
  // Moves 4->5 and 5->6 touch the obstacle: 2 cells flown, 7 rolled.
  EXPECT_NEAR(path->fly_m, 0.10, 1e-12);
  EXPECT_NEAR(path->roll_m, 0.35, 1e-12);
  EXPECT_EQ(path->switches, 2);
  ASSERT_EQ(path->segments.size(), 3u);
  EXPECT_EQ(path->segments[1].mode, MotionMode::kFlying);
  EXPECT_EQ(path->segments[1].from, (Cell{4, 0}));
  EXPECT_EQ(path->segments[1].to, (Cell{6, 0}));
  // Turning points: start, both mode changes, goal; segments index them.
  ASSERT_EQ(path->waypoints.size(), 4u);
  EXPECT_EQ(path->segments[1].first_point, 1);
  EXPECT_EQ(path->segments[1].last_point, 2);
  EXPECT_EQ(path->waypoints[path->segments[2].last_point], (Cell{9, 0}));
  // Eq. 10 and 12: 0.10 m * 800 J/m + 0.35 m * 400 J/m.
  EXPECT_NEAR(path->energy_j, 220.0, 1e-9);
}

// A 5-column obstacle wall (rows 0-3) with a gap at row 4, 1 m cells.
// Flying straight: 14 m rolled + 6 m flown; rolling round: 12 + 8 sqrt(2) m.
LayeredGrid WallWithGap() {
  LayeredGrid grid(21, 7, 0);
  for (int y = 0; y <= 3; ++y) {
    for (int x = 8; x <= 12; ++x) grid.at(x, y) = 60;
  }
  return grid;
}

TEST(JumpAStar, BetaOneFliesOverTheWall) {
  JumpAStarPlanner planner;
  absl::StatusOr<MultiModalPath> path = planner.Plan(WallWithGap(), {0, 0}, {20, 0}, MetreCells(1));
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_NEAR(path->fly_m, 6.0, 1e-9);
  EXPECT_NEAR(path->roll_m, 14.0, 1e-9);
  EXPECT_EQ(path->switches, 2);
  EXPECT_NEAR(path->energy_j, 6 * 800 + 14 * 400, 1e-9);
  // Eq. 14 with e in kJ: 1 * 20 m + 1 * 10.4 kJ.
  EXPECT_NEAR(path->cost, 30.4, 1e-9);
}

TEST(JumpAStar, BetaFiveRollsRoundTheWall) {
  JumpAStarPlanner planner;
  absl::StatusOr<MultiModalPath> path = planner.Plan(WallWithGap(), {0, 0}, {20, 0}, MetreCells(5));
  ASSERT_TRUE(path.ok()) << path.status();
  const double round = 12 + 8 * kSqrt2;
  EXPECT_DOUBLE_EQ(path->fly_m, 0.0);
  EXPECT_NEAR(path->roll_m, round, 1e-9);
  EXPECT_EQ(path->switches, 0);
  EXPECT_NEAR(path->energy_j, 400 * round, 1e-9);
  EXPECT_NEAR(path->cost, (1 + 5 * 0.4) * round, 1e-9);
}

TEST(JumpAStar, TypedFailures) {
  LayeredGrid grid(5, 5, 0);
  for (int y = 0; y < 5; ++y) grid.at(2, y) = kStructureValue;
  JumpAStarPlanner planner;
  const JumpAStarOptions options;
  EXPECT_EQ(PlanFailureOf(planner.Plan(grid, {0, 0}, {4, 4}, options).status()),
            PlanFailure::kNoPath);
  EXPECT_EQ(PlanFailureOf(planner.Plan(grid, {2, 1}, {4, 4}, options).status()),
            PlanFailure::kStartOccupied);
  EXPECT_EQ(PlanFailureOf(planner.Plan(grid, {0, 0}, {2, 3}, options).status()),
            PlanFailure::kGoalOccupied);
  EXPECT_EQ(planner.Plan(grid, {0, 0}, {5, 0}, options).status().code(),
            absl::StatusCode::kInvalidArgument);
}

TEST(JumpAStar, JumpPruningKeepsTheOptimalCost) {
  JumpAStarPlanner planner;
  for (uint32_t seed = 1; seed <= 12; ++seed) {
    RandomLayeredMapSpec spec;
    spec.size_m = 12.0;
    spec.obstacle_count = 25;
    spec.seed = seed;
    const RandomLayeredMap map = MakeRandomLayeredMap(spec);
    for (double beta : {0.0, 1.0, 2.5, 5.0}) {
      JumpAStarOptions options;
      options.beta = beta;
      absl::StatusOr<MultiModalPath> jumped = planner.Plan(map.grid, map.start, map.goal, options);
      options.jump_pruning = false;
      absl::StatusOr<MultiModalPath> plain = planner.Plan(map.grid, map.start, map.goal, options);
      ASSERT_TRUE(jumped.ok() && plain.ok()) << "seed " << seed;
      EXPECT_NEAR(jumped->cost, plain->cost, 1e-9) << "seed " << seed << " beta " << beta;
      EXPECT_LE(jumped->expansions, plain->expansions);
    }
  }
}

// Queries on prepared tables with the landmark bound must cost exactly what
// full A* finds, for every start/goal pair.
TEST(JumpAStar, LandmarkBoundKeepsTheOptimalCost) {
  RandomLayeredMapSpec spec;
  spec.size_m = 12.0;
  spec.obstacle_count = 25;
  const RandomLayeredMap map = MakeRandomLayeredMap(spec);
  JumpAStarOptions options;
  const RegionTables tables(map.grid);
  const LandmarkHeuristic landmarks(map.grid, StepCostsOf(options));
  JumpAStarPlanner warm;
  JumpAStarPlanner reference;
  JumpAStarOptions plain = options;
  plain.jump_pruning = false;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(1, map.grid.width() - 2);
  int compared = 0;
  while (compared < 40) {
    const Cell start{coord(rng), coord(rng)};
    const Cell goal{coord(rng), coord(rng)};
    absl::StatusOr<MultiModalPath> jumped = warm.Plan(tables, &landmarks, start, goal, options);
    absl::StatusOr<MultiModalPath> full = reference.Plan(map.grid, start, goal, plain);
    ASSERT_EQ(jumped.ok(), full.ok());
    if (!full.ok()) continue;
    EXPECT_NEAR(jumped->cost, full->cost, 1e-9) << start.x << "," << start.y;
    EXPECT_LE(jumped->expansions, full->expansions);
    ++compared;
  }
}

// Cold queries (tables built per query, octile bound) between random cells
// on maps with obstacles and structure walls cost exactly what full A* finds, and the returned
// cells -- including the runs through skipped diagonal jump points -- add up to that cost.
TEST(JumpAStar, ColdQueriesBetweenRandomCellsMatchPlainAStar) {
  JumpAStarPlanner jumped_planner;
  JumpAStarPlanner reference;
  std::mt19937 rng(3);
  int compared = 0;
  for (uint32_t seed = 1; seed <= 12; ++seed) {
    RandomLayeredMap map =
        MakeRandomLayeredMap({.size_m = 6.0, .obstacle_count = 20, .seed = seed});
    std::uniform_int_distribution<int> coord(1, map.grid.width() - 2);
    // Short structure walls inside the map too, so jumps meet forced
    // neighbours (the random map has structure only at its border).
    for (int wall = 0; wall < 30; ++wall) {
      const Cell from{coord(rng), coord(rng)};
      const bool along_x = wall % 2 == 0;
      for (int k = 0; k < 15; ++k) {
        const Cell c{from.x + (along_x ? k : 0), from.y + (along_x ? 0 : k)};
        if (map.grid.Contains(c)) map.grid.at(c) = kStructureValue;
      }
    }
    for (double beta : {0.0, 1.0, 5.0}) {
      JumpAStarOptions options;
      options.beta = beta;
      JumpAStarOptions plain = options;
      plain.jump_pruning = false;
      for (int query = 0; query < 30; ++query) {
        const Cell start{coord(rng), coord(rng)};
        const Cell goal{coord(rng), coord(rng)};
        absl::StatusOr<MultiModalPath> jumped = jumped_planner.Plan(map.grid, start, goal, options);
        absl::StatusOr<MultiModalPath> full = reference.Plan(map.grid, start, goal, plain);
        ASSERT_EQ(jumped.ok(), full.ok());
        if (!full.ok()) continue;
        EXPECT_NEAR(jumped->cost, full->cost, 1e-9) << "seed " << seed << " beta " << beta;
        // Eq. 14 recomputed from the summarised cells: alpha g + beta e.
        EXPECT_NEAR(options.alpha * jumped->length_m +
                        options.beta * jumped->energy_j / options.energy_unit_j,
                    jumped->cost, 1e-9);
        EXPECT_LE(jumped->expansions, full->expansions);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 700);
}

// A landmark bound built for other costs is not used (it could overestimate).
TEST(JumpAStar, LandmarksForOtherCostsAreIgnored) {
  const RandomLayeredMap map = MakeRandomLayeredMap({.size_m = 12.0, .obstacle_count = 25});
  JumpAStarOptions cheap_flight;
  cheap_flight.beta = 0.0;
  JumpAStarOptions options;
  options.beta = 5.0;
  const RegionTables tables(map.grid);
  const LandmarkHeuristic wrong(map.grid, StepCostsOf(options));
  JumpAStarPlanner planner;
  absl::StatusOr<MultiModalPath> with =
      planner.Plan(tables, &wrong, map.start, map.goal, cheap_flight);
  absl::StatusOr<MultiModalPath> without =
      planner.Plan(map.grid, map.start, map.goal, cheap_flight);
  ASSERT_TRUE(with.ok() && without.ok());
  EXPECT_DOUBLE_EQ(with->cost, without->cost);
  EXPECT_EQ(with->expansions, without->expansions);
}

TEST(JumpAStar, Table2TrendOnTheSeedMap) {
  const RandomLayeredMap map = MakeRandomLayeredMap({});
  JumpAStarPlanner planner;
  std::vector<MultiModalPath> rows;
  for (double beta : {1.0, 2.5, 5.0}) {
    JumpAStarOptions options;
    options.beta = beta;
    absl::StatusOr<MultiModalPath> path = planner.Plan(map.grid, map.start, map.goal, options);
    ASSERT_TRUE(path.ok()) << path.status();
    rows.push_back(*path);
  }
  // Table 2 shape: fly distance, switches and energy fall as beta/alpha
  // grows, to no flying at 5; the path rolls further round instead.
  EXPECT_GT(rows[0].fly_m, rows[1].fly_m);
  EXPECT_GT(rows[1].fly_m, 0.0);
  EXPECT_DOUBLE_EQ(rows[2].fly_m, 0.0);
  EXPECT_GT(rows[0].switches, rows[1].switches);
  EXPECT_GT(rows[1].switches, 0);
  EXPECT_EQ(rows[2].switches, 0);
  EXPECT_GT(rows[0].energy_j, rows[1].energy_j);
  EXPECT_GT(rows[1].energy_j, rows[2].energy_j);
  EXPECT_LT(rows[0].roll_m, rows[1].roll_m);
  EXPECT_LT(rows[1].roll_m, rows[2].roll_m);
}

}  // namespace
}  // namespace semnav::planning
