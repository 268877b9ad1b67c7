#include "services/planning/core/trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace semnav::planning {
namespace {

TEST(AllocateTime, TrapezoidOnAStraightLine) {
  // 10 m at 5 cm: accelerate 0 -> 1 m/s over 0.25 m (0.5 s), cruise 9.5 m
  // (9.5 s), brake over 0.25 m (0.5 s): 10.5 s in all.
  std::vector<Point2> line;
  for (int i = 0; i <= 200; ++i) line.push_back({i * 0.05, 0.0});
  const std::vector<TrajectoryPoint> traj = AllocateTime(line, {});
  EXPECT_NEAR(traj.back().t, 10.5, 1e-9);
  EXPECT_DOUBLE_EQ(traj.front().speed, 0.0);
  EXPECT_NEAR(traj[5].speed, 1.0, 1e-12);  // 0.25 m in
  EXPECT_NEAR(traj[3].speed, std::sqrt(2 * 2.0 * 0.15), 1e-12);
  EXPECT_DOUBLE_EQ(traj.back().speed, 0.0);
}

TEST(AllocateTime, YawRateLimitsSpeedOnACurve) {
  // A 0.25 m radius arc: yaw rate 2 rad/s allows 2 * 0.25 = 0.5 m/s.
  std::vector<Point2> arc;
  for (int i = 0; i <= 200; ++i) {
    const double a = i * std::numbers::pi / 200;
    arc.push_back({0.25 * std::cos(a), 0.25 * std::sin(a)});
  }
  const std::vector<TrajectoryPoint> traj = AllocateTime(arc, {});
  EXPECT_NEAR(traj[100].speed, 0.5, 1e-6);
  EXPECT_NEAR(std::abs(traj[100].yaw), std::numbers::pi, 0.02);  // moving in -x at the top
}

TEST(SmoothPath, RoundsACornerWithoutEnteringObstacles) {
  // An L with its corner at (1, 0) m on 0.1 m cells (origin -0.5); the
  // inside of the corner beyond x < 0.7, y >= 0.3 is blocked, leaving room
  // to cut the corner by up to 0.3 m but no more.
  PassabilityGrid grid(30, 30, 1);
  for (int r = 8; r < 30; ++r) {
    for (int c = 0; c < 12; ++c) grid.at(c, r) = 0;
  }
  const GridGeometry geometry{0.1, -0.5, -0.5};
  const std::vector<Point2> path = {{-0.45, 0.0}, {1.0, 0.0}, {1.0, 1.5}};
  const std::vector<Point2> smooth = SmoothPath(grid, geometry, path, {});
  ASSERT_GT(smooth.size(), 20u);
  EXPECT_DOUBLE_EQ(smooth.front().x, -0.45);
  EXPECT_DOUBLE_EQ(smooth.back().y, 1.5);
  double corner_cut = 0.0;
  for (const Point2& p : smooth) {
    const int c = static_cast<int>(std::floor((p.x + 0.5) / 0.1));
    const int r = static_cast<int>(std::floor((p.y + 0.5) / 0.1));
    ASSERT_TRUE(IsFree(grid, c, r)) << p.x << ", " << p.y;
    corner_cut = std::max(corner_cut, std::min(1.0 - p.x, p.y));
  }
  EXPECT_GT(corner_cut, 0.05);  // the 90-degree corner is rounded off
}

}  // namespace
}  // namespace semnav::planning
