#include "clients/sim/loop/stop_on_sight.h"

#include <gtest/gtest.h>

#include <cmath>

#include "clients/sim/core/test_worlds.h"

namespace semnav::sim::loop {
namespace {

constexpr double kHalfFov = 0.547;  // 2 atan(320 / 525) / 2, the simulator's camera
constexpr double kCameraHeight = 0.88;

// A 2.0 x 1.6 m bed with its footprint over x in [1, 3], y in [0.7, 2.3].
World WithBed() {
  World world = testing::OpenWorld();
  world.objects.push_back(testing::Object("bed_1", "bed", testing::Box(2.0, 1.5, 2.0, 1.6, 0.55)));
  return world;
}

// Along y = 0 from x = -4 to 4 in 5 cm steps, heading +x.
std::vector<Eigen::Vector2d> PastTheBed() {
  std::vector<Eigen::Vector2d> path;
  for (int i = 0; i <= 160; ++i) path.emplace_back(-4.0 + 0.05 * i, 0.0);
  return path;
}

TEST(StopOnSightTest, TheRobotStopsWhereItFirstSeesTheTargetWithinReach) {
  // Within 0.8 m of the footprint from x = 1 - sqrt(0.8^2 - 0.7^2) = 0.613 on. There the bed's far
  // near-side corner, pulled in to (2.9, 0.78), lies 19 deg off the heading, inside the 31 deg
  // half field of view; its near corner (58 deg) and centre (47 deg) do not.
  const World world = WithBed();
  const Scene scene = Scene::Build(world);
  const std::vector<Eigen::Vector2d> path = PastTheBed();
  const size_t stop =
      StopOnSight(path, world, scene, world.objects[0], kCameraHeight, kHalfFov, 6.0, 0.8);
  EXPECT_NEAR(path[stop].x(), 0.65, 1e-9);
  // With a reach of 0.5 m it never comes close enough (the path passes 0.7 m from the bed).
  EXPECT_EQ(StopOnSight(path, world, scene, world.objects[0], kCameraHeight, kHalfFov, 6.0, 0.5),
            path.size() - 1);
}

TEST(StopOnSightTest, ATargetBehindAWallIsNeverSeen) {
  World world = WithBed();
  world.obstacles.push_back(Obstacle{"wall", Rgb{}, testing::Box(0.0, 0.4, 10.0, 0.1, 2.0)});
  const Scene scene = Scene::Build(world);
  const std::vector<Eigen::Vector2d> path = PastTheBed();
  EXPECT_EQ(StopOnSight(path, world, scene, world.objects[0], kCameraHeight, kHalfFov, 6.0, 0.8),
            path.size() - 1);
}

}  // namespace
}  // namespace semnav::sim::loop
