#include "clients/sim/core/ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "clients/sim/core/rng.h"
#include "clients/sim/core/shape_queries.h"

namespace semnav::sim {
namespace {

World EmptyWorld() {
  World world;
  world.name = "test";
  world.bounds_min = Eigen::Vector2d(-10, -10);
  world.bounds_max = Eigen::Vector2d(10, 10);
  return world;
}

Obstacle BoxObstacle(Eigen::Vector2d center, Eigen::Vector3d size, double yaw = 0.0) {
  BoxShape box;
  box.center = center;
  box.size = size;
  box.yaw = yaw;
  return Obstacle{"wall", Rgb{}, box};
}

TEST(SimRayCasterTest, WallAtKnownDistance) {
  World world = EmptyWorld();
  // Wall 0.2 m thick centred at x = 5.1: its near face is the plane x = 5.
  world.obstacles.push_back(BoxObstacle({5.1, 0.0}, {0.2, 8.0, 2.5}));
  const Scene scene = Scene::Build(world);
  RayCaster caster(scene);
  const auto hit = caster.Cast({0, 0, 1}, {1, 0, 0}, 0.0, 8.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 5.0, 1e-9);
  EXPECT_EQ(hit->solid, 0);
  EXPECT_NEAR(hit->normal.x(), -1.0, 1e-9);
  // An oblique ray at 30 degrees meets the same plane after 5 / cos(30 deg).
  const double a = std::numbers::pi / 6;
  const auto oblique = caster.Cast({0, 0, 1}, {std::cos(a), std::sin(a), 0}, 0.0, 8.0);
  ASSERT_TRUE(oblique.has_value());
  EXPECT_NEAR(oblique->t, 5.0 / std::cos(a), 1e-9);
}

TEST(SimRayCasterTest, RangeLimitsExcludeHits) {
  World world = EmptyWorld();
  world.obstacles.push_back(BoxObstacle({5.1, 0.0}, {0.2, 4.0, 2.5}));
  const Scene scene = Scene::Build(world);
  RayCaster caster(scene);
  EXPECT_FALSE(caster.Cast({0, 0, 1}, {1, 0, 0}, 0.0, 4.99).has_value());
  // A ray starting past the near face (t_min beyond it) must not report the face behind t_min.
  EXPECT_FALSE(caster.Cast({0, 0, 1}, {1, 0, 0}, 5.05, 8.0).has_value());
  // Above the wall top (2.5 m) nothing is hit.
  EXPECT_FALSE(caster.Cast({0, 0, 2.6}, {1, 0, 0}, 0.0, 8.0).has_value());
}

TEST(SimRayCasterTest, RotatedBoxCorner) {
  World world = EmptyWorld();
  // A 2 x 2 box turned 45 degrees about (4, 0): its corner points at the origin,
  // at x = 4 - sqrt(2).
  world.obstacles.push_back(BoxObstacle({4.0, 0.0}, {2.0, 2.0, 1.0}, std::numbers::pi / 4));
  const Scene scene = Scene::Build(world);
  RayCaster caster(scene);
  const auto hit = caster.Cast({0, 0, 0.5}, {1, 0, 0}, 0.0, 8.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 4.0 - std::sqrt(2.0), 1e-9);
  // Slightly off the corner the ray hits a face whose normal is at 45 degrees.
  const auto side = caster.Cast({0, 0.1, 0.5}, {1, 0, 0}, 0.0, 8.0);
  ASSERT_TRUE(side.has_value());
  EXPECT_NEAR(side->t, 4.0 - std::sqrt(2.0) + 0.1, 1e-9);
  EXPECT_NEAR(std::abs(side->normal.x()), std::sqrt(0.5), 1e-9);
}

TEST(SimRayCasterTest, FloorAndCeilingPlanes) {
  World world = EmptyWorld();
  world.ceiling_height = 3.0;
  const Scene scene = Scene::Build(world);
  RayCaster caster(scene);
  const Eigen::Vector3d down = Eigen::Vector3d(1, 0, -1).normalized();
  const auto floor = caster.Cast({0, 0, 1}, down, 0.0, 8.0);
  ASSERT_TRUE(floor.has_value());
  EXPECT_EQ(floor->solid, kFloorSurface);
  EXPECT_NEAR(floor->t, std::sqrt(2.0), 1e-9);
  const auto ceiling = caster.Cast({0, 0, 1}, {0, 0, 1}, 0.0, 8.0);
  ASSERT_TRUE(ceiling.has_value());
  EXPECT_EQ(ceiling->solid, kCeilingSurface);
  EXPECT_NEAR(ceiling->t, 2.0, 1e-9);
}

TEST(SimRayCasterTest, ConcavePrismNotch) {
  World world = EmptyWorld();
  // A U-shaped prism open towards -x: the notch spans y in (-1, 1) from x = 2 to 4.
  PrismShape u;
  u.polygon = {{2, -3}, {6, -3}, {6, 3}, {2, 3}, {2, 1}, {4, 1}, {4, -1}, {2, -1}};
  u.height = 2.0;
  world.obstacles.push_back(Obstacle{"building", Rgb{}, u});
  const Scene scene = Scene::Build(world);
  RayCaster caster(scene);
  const auto into_notch = caster.Cast({0, 0, 1}, {1, 0, 0}, 0.0, 8.0);
  ASSERT_TRUE(into_notch.has_value());
  EXPECT_NEAR(into_notch->t, 4.0, 1e-9);
  const auto arm = caster.Cast({0, 2, 1}, {1, 0, 0}, 0.0, 8.0);
  ASSERT_TRUE(arm.has_value());
  EXPECT_NEAR(arm->t, 2.0, 1e-9);
  // Straight down onto the roof at z = 2.
  const auto roof = caster.Cast({5, 0, 3}, {0, 0, -1}, 0.0, 8.0);
  ASSERT_TRUE(roof.has_value());
  EXPECT_NEAR(roof->t, 1.0, 1e-9);
  EXPECT_NEAR(roof->normal.z(), 1.0, 1e-9);
}

// The grid traversal must find exactly what testing every solid finds.
TEST(SimRayCasterTest, GridMatchesBruteForce) {
  World world = EmptyWorld();
  Rng rng(7);
  for (int i = 0; i < 60; ++i) {
    world.obstacles.push_back(BoxObstacle(
        {rng.Uniform(-9, 9), rng.Uniform(-9, 9)},
        {rng.Uniform(0.1, 2), rng.Uniform(0.1, 2), rng.Uniform(0.2, 3)}, rng.Uniform(0, 3)));
  }
  const Scene scene = Scene::Build(world, 0.7);
  RayCaster caster(scene);
  for (int r = 0; r < 2000; ++r) {
    const Eigen::Vector3d origin(rng.Uniform(-9, 9), rng.Uniform(-9, 9), rng.Uniform(0.1, 2.5));
    const Eigen::Vector3d dir =
        Eigen::Vector3d(rng.Normal(), rng.Normal(), 0.3 * rng.Normal()).normalized();
    double brute = 20.0;
    for (const SceneSolid& s : scene.solids()) {
      if (auto hit = IntersectRay(s.shape, origin, dir, 0.0, brute)) brute = hit->t;
    }
    if (dir.z() < 0) brute = std::min(brute, -origin.z() / dir.z());
    const auto hit = caster.Cast(origin, dir, 0.0, 20.0);
    ASSERT_EQ(hit.has_value(), brute < 20.0) << r;
    if (hit) {
      EXPECT_NEAR(hit->t, brute, 1e-9) << r;
    }
  }
}

}  // namespace
}  // namespace semnav::sim

namespace semnav::sim {
namespace {

TEST(SimSceneTest, AutomaticCellSizeShrinksForDenseGeometry) {
  World sparse = EmptyWorld();
  sparse.obstacles.push_back(BoxObstacle({0, 0}, {1, 1, 1}));
  EXPECT_DOUBLE_EQ(Scene::Build(sparse).cell_size(), 1.0);
  // 900 small boxes in a 20 x 20 x 1 m extent: 900 references > 400 cells of 1 m, while
  // 0.5 m cells give 1800 references (two layers each) <= 3200 cells.
  World dense = EmptyWorld();
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) {
      dense.obstacles.push_back(BoxObstacle({-9.5 + i * 0.2, -9.5 + j * 0.2}, {0.1, 0.1, 0.5}));
    }
  }
  EXPECT_DOUBLE_EQ(Scene::Build(dense).cell_size(), 0.5);
  EXPECT_DOUBLE_EQ(Scene::Build(dense, 0.7).cell_size(), 0.7);
}

}  // namespace
}  // namespace semnav::sim
