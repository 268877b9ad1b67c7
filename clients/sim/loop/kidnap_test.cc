#include "clients/sim/loop/kidnap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>

#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/test_worlds.h"

namespace semnav::sim::loop {
namespace {

// A room 6.4 m across around the origin, split at x = 0 by a wall with a 1.2 m door at y = 0.
GroundTruthGrid TwoRooms() {
  World world = testing::OpenWorld();
  for (const auto& [x, y, sx, sy] :
       std::vector<std::array<double, 4>>{{0.0, 3.3, 6.8, 0.2},
                                          {0.0, -3.3, 6.8, 0.2},
                                          {3.3, 0.0, 0.2, 6.8},
                                          {-3.3, 0.0, 0.2, 6.8},
                                          {0.0, 2.0, 0.2, 2.6},  // the split, above the door
                                          {0.0, -2.0, 0.2, 2.6}}) {
    world.obstacles.push_back(Obstacle{"wall", Rgb{}, testing::Box(x, y, sx, sy, 2.0)});
  }
  return RasterizeOccupancy(world, BodyRaster(RobotConfig::ForModality(Modality::kGround), 0.0));
}

// The robot went up and down the left room along x = -1.5 and stands at its middle.
std::vector<Eigen::Vector2d> LeftRoomPath() {
  std::vector<Eigen::Vector2d> path;
  for (double y = -2.5; y <= 2.5; y += 0.25) path.emplace_back(-1.5, y);
  return path;
}

double DistanceToPath(const Eigen::Vector2d& at, const std::vector<Eigen::Vector2d>& path) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : path) best = std::min(best, (p - at).norm());
  return best;
}

TEST(KidnapDestinationTest, TheRobotIsCarriedOnlyToPlacesItWentNearWithinTheSpaceItReaches) {
  const GroundTruthGrid grid = TwoRooms();
  const Pose robot{Eigen::Vector3d(-1.5, 0.0, 0.0), 0.0};
  const KidnapConfig config;  // 2-5 m away, within 1 m of the path
  for (uint64_t seed = 0; seed < 40; ++seed) {
    Rng rng(seed);
    const std::optional<Pose> to = KidnapDestination(grid, robot, LeftRoomPath(), config, rng);
    ASSERT_TRUE(to.has_value()) << seed;
    const Eigen::Vector2d at = to->position.head<2>();
    const double distance = (at - robot.position.head<2>()).norm();
    EXPECT_GE(distance, 2.0) << seed;
    EXPECT_LE(distance, 5.0) << seed;
    // The right room, through the door, is free, reachable and 2-5 m away, but never seen.
    EXPECT_LT(at.x(), -0.3) << seed << ": " << at.transpose();
    EXPECT_LE(DistanceToPath(at, LeftRoomPath()), 1.0) << seed;
    EXPECT_LT(at.cwiseAbs().maxCoeff(), 3.2) << seed;
    EXPECT_GE(to->yaw, -M_PI);
    EXPECT_LT(to->yaw, M_PI);
  }
  // Deterministic by the random stream.
  Rng a(7);
  Rng b(7);
  EXPECT_EQ(KidnapDestination(grid, robot, LeftRoomPath(), config, a)->position,
            KidnapDestination(grid, robot, LeftRoomPath(), config, b)->position);
}

TEST(KidnapDestinationTest, ARobotThatWentNowhereIsNotCarried) {
  // Its only place is where it stands, and every destination lies at least 2 m from there.
  const Pose robot{Eigen::Vector3d(-1.5, 0.0, 0.0), 0.0};
  Rng rng(1);
  EXPECT_FALSE(KidnapDestination(TwoRooms(), robot, {robot.position.head<2>()}, KidnapConfig{}, rng)
                   .has_value());
}

}  // namespace
}  // namespace semnav::sim::loop
