#include "services/planning/core/layered_inflation.h"

#include <gtest/gtest.h>

#include "services/planning/core/jump_astar.h"

namespace semnav::planning {
namespace {

TEST(LayeredInflation, RaisesCellsNearObstaclesToTheTallestAndWidensStructure) {
  LayeredGrid grid(9, 5, 0);
  grid.at(2, 2) = 30;  // a low crate
  grid.at(3, 2) = 60;  // a taller one beside it
  grid.at(8, 2) = kStructureValue;
  const LayeredGrid out = InflateLayeredGrid(grid, 1.0);
  EXPECT_EQ(out.at(2, 2), 60);  // within 1 cell of the taller crate
  EXPECT_EQ(out.at(1, 2), 30);  // only the low one is this close
  EXPECT_EQ(out.at(4, 2), 60);
  EXPECT_EQ(out.at(3, 1), 60);
  EXPECT_EQ(out.at(2, 1), 30);  // beside the low one; the tall one is sqrt(2) cells away
  EXPECT_EQ(out.at(1, 1), 0);   // diagonal: sqrt(2) > 1 cell from (2, 2)
  EXPECT_EQ(out.at(5, 2), 0);
  EXPECT_EQ(out.at(7, 2), kStructureValue);
  EXPECT_EQ(out.at(8, 1), kStructureValue);
  EXPECT_EQ(out.at(6, 2), 0);
  // Radius 0: unchanged.
  EXPECT_EQ(InflateLayeredGrid(grid, 0.0).values(), grid.values());
}

TEST(LayeredInflation, NearestPassableCellSkipsStructure) {
  LayeredGrid grid(5, 5, kStructureValue);
  grid.at(4, 2) = 0;
  grid.at(0, 2) = 0;
  EXPECT_EQ(NearestPassableCell(grid, {2, 2}, 2.0), (Cell{0, 2}));  // a tie: the lower column
  EXPECT_FALSE(NearestPassableCell(grid, {2, 2}, 1.5).has_value());
  grid.at(2, 3) = 50;  // an obstacle can be flown from, and it is nearer
  EXPECT_EQ(NearestPassableCell(grid, {2, 2}, 2.0), (Cell{2, 3}));
}

// Regression (flyroll_01/02: "robot blocked: collision with crate"): without the footprint the
// search rolled the robot's centre along the crate's edge, 0 cm from it; on the inflated grid the
// rolling path keeps the radius, and where the gap between two crates is narrower than the robot
// it flies over them at the taller one's height.
TEST(LayeredInflation, InflatedPathsKeepTheRadiusOrFlyOverTheGap) {
  // 1 m cells: crates at columns 4-6, rows 0-1 (value 40) and rows 3-6 (value 70); the gap row 2
  // is one cell wide.
  LayeredGrid grid(11, 7, 0);
  for (int x = 4; x <= 6; ++x) {
    for (int y = 0; y <= 1; ++y) grid.at(x, y) = 40;
    for (int y = 3; y <= 6; ++y) grid.at(x, y) = 70;
  }
  JumpAStarOptions options;
  options.resolution_m = 1.0;
  JumpAStarPlanner planner;
  absl::StatusOr<MultiModalPath> bare = planner.Plan(grid, {0, 2}, {10, 2}, options);
  ASSERT_TRUE(bare.ok()) << bare.status();
  EXPECT_EQ(bare->fly_m, 0.0);  // rolls through the 1-cell gap, touching both crates
  const LayeredGrid inflated = InflateLayeredGrid(grid, 1.0);
  absl::StatusOr<MultiModalPath> wide = planner.Plan(inflated, {0, 2}, {10, 2}, options);
  ASSERT_TRUE(wide.ok()) << wide.status();
  // Columns 4-6 of row 2 are within a cell of both crates: the 4 moves from column 3 to 7 are
  // flown, at the taller crate's value.
  EXPECT_NEAR(wide->fly_m, 4.0, 1e-9);
  ASSERT_EQ(wide->segments.size(), 3u);
  EXPECT_EQ(wide->segments[1].mode, MotionMode::kFlying);
  EXPECT_EQ(wide->segments[1].top, 70);
  EXPECT_EQ(wide->segments[0].top, 0);
}

TEST(LayeredInflation, FlightAltitudeInvertsEquationThree) {
  // h_f 0.1, h_c 2.3: value 40 is 0.1 + 0.405 * 2.2 = 0.991 m, plus 0.25 m.
  EXPECT_NEAR(FlightAltitude(40, 0.1, 2.3, 0.25), 1.241, 1e-9);
  EXPECT_EQ(FlightAltitude(0, 0.1, 2.3, 0.25), 0.0);
  EXPECT_EQ(FlightAltitude(40, 0.0, 0.0, 0.25), 0.0);  // no heights on the grid
}

TEST(LayeredInflation, PrependStartJoinsTheFirstSegment) {
  LayeredGrid grid(6, 1, 0);
  JumpAStarOptions options;
  options.resolution_m = 1.0;
  JumpAStarPlanner planner;
  absl::StatusOr<MultiModalPath> path = planner.Plan(grid, {2, 0}, {5, 0}, options);
  ASSERT_TRUE(path.ok());
  PrependStart({0, 0}, options, &*path);
  ASSERT_EQ(path->waypoints.size(), 3u);
  EXPECT_EQ(path->waypoints[0], (Cell{0, 0}));
  EXPECT_EQ(path->segments[0].first_point, 0);
  EXPECT_EQ(path->segments[0].last_point, 2);
  EXPECT_NEAR(path->length_m, 5.0, 1e-9);
  EXPECT_NEAR(path->energy_j, 2000.0, 1e-9);  // 5 m rolled at 400 J/m
}

}  // namespace
}  // namespace semnav::planning
