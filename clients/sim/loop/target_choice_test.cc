#include "clients/sim/loop/target_choice.h"

#include <gtest/gtest.h>

#include <cmath>

#include "clients/sim/core/test_worlds.h"

namespace semnav::sim::loop {
namespace {

TEST(SimLoopTargetChoiceTest, SkipsTargetsBehindWallsAndTakesTheNearestFreeOne) {
  World world = testing::OpenWorld();
  // A chair 2.5 m east behind a wall, a bottle 3 m north in the open, a tv 4.5 m west (too far).
  world.obstacles.push_back(Obstacle{"wall", Rgb{}, testing::Box(1.2, 0.0, 0.1, 3.0, 2.0)});
  world.objects.push_back(
      testing::Object("chair_1", "chair", testing::Box(2.5, 0.0, 0.5, 0.5, 0.9)));
  world.objects.push_back(
      testing::Object("bottle_1", "bottle", testing::Box(0.0, 3.0, 0.2, 0.2, 0.3)));
  world.objects.push_back(testing::Object("tv_1", "tv", testing::Box(-4.5, 0.0, 0.2, 1.0, 0.8)));
  RasterOptions raster;
  const GroundTruthGrid grid = RasterizeOccupancy(world, raster);
  const std::optional<TargetChoice> choice =
      PickInSightTarget(world, grid, Eigen::Vector2d::Zero(), 1.5, 3.5, 1.0);
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->label, "bottle");
  EXPECT_EQ(choice->object_index, 1);
  EXPECT_NEAR(choice->distance_m, 3.0, 1e-9);
  EXPECT_NEAR(choice->yaw_to_target, M_PI / 2, 1e-9);
  // A second bottle's footprint 0.94 m from the start (under min_m): no bottle episode.
  world.objects.push_back(
      testing::Object("bottle_2", "bottle", testing::Box(0.9, -0.6, 0.2, 0.2, 0.3)));
  EXPECT_FALSE(PickInSightTarget(world, RasterizeOccupancy(world, raster), Eigen::Vector2d::Zero(),
                                 1.5, 3.5, 1.0)
                   .has_value());
  world.objects.pop_back();
  // Without the bottle nothing qualifies.
  world.objects.erase(world.objects.begin() + 1);
  EXPECT_FALSE(PickInSightTarget(world, RasterizeOccupancy(world, raster), Eigen::Vector2d::Zero(),
                                 1.5, 3.5, 1.0)
                   .has_value());
}

}  // namespace
}  // namespace semnav::sim::loop
