#include "services/mapping/core/scan_matcher.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::mapping {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A 6 x 4 m room (walls one cell thick), with or without a 1 x 1 m cabinet in one corner, at
// 5 cm cells, origin (0, 0).
OccupiedRaster Room(bool cabinet = true) {
  OccupiedRaster map;
  map.resolution = 0.05;
  map.width = 140;  // 7 m: a half-metre margin around the room
  map.height = 100;
  map.occupied.assign(static_cast<size_t>(map.width) * map.height, 0);
  auto set = [&](double x, double y) {
    const int col = static_cast<int>(std::floor(x / map.resolution));
    const int row = static_cast<int>(std::floor(y / map.resolution));
    map.occupied[static_cast<size_t>(row) * map.width + col] = 1;
  };
  for (double x = 0.5; x <= 6.5; x += 0.025) {
    set(x, 0.5);
    set(x, 4.5);
  }
  for (double y = 0.5; y <= 4.5; y += 0.025) {
    set(0.5, y);
    set(6.5, y);
  }
  for (double t = 5.5; cabinet && t <= 6.5; t += 0.025) {
    set(t, 3.5);  // the cabinet's front and side
    set(5.5, t - 2.0);
  }
  return map;
}

// What the depth camera sees of the room from inside, as points in the map frame.
std::vector<Eigen::Vector2d> RoomPointsInMap() {
  std::vector<Eigen::Vector2d> points;
  for (double x = 0.52; x <= 5.5; x += 0.02) points.emplace_back(x, 4.52);
  for (double x = 0.52; x <= 6.48; x += 0.02) points.emplace_back(x, 0.52);
  for (double y = 0.52; y <= 4.48; y += 0.02) points.emplace_back(0.52, y);
  for (double y = 0.52; y <= 3.5; y += 0.02) points.emplace_back(6.48, y);
  for (double t = 5.5; t <= 6.48; t += 0.02) points.emplace_back(t, 3.52);
  return points;
}

// The robot's reported frame: `truth` takes it to the map.
std::vector<Eigen::Vector2d> ScanInReportedFrame(const PlanarCorrection& truth) {
  const PlanarCorrection reported_from_map = truth.Inverse();
  std::vector<Eigen::Vector2d> scan;
  for (const Eigen::Vector2d& p : RoomPointsInMap()) scan.push_back(reported_from_map.Apply(p));
  return scan;
}

TEST(PlanarCorrectionTest, InverseUndoesIt) {
  // p -> R(90 deg) p + (1, 0); back: p -> R(-90 deg) (p - (1, 0)) = R(-90 deg) p + (0, 1).
  const PlanarCorrection back = PlanarCorrection{1.0, 0.0, 90 * kDeg}.Inverse();
  EXPECT_NEAR(back.x, 0.0, 1e-12);
  EXPECT_NEAR(back.y, 1.0, 1e-12);
  EXPECT_NEAR(back.yaw, -90 * kDeg, 1e-12);
  const Eigen::Vector2d p = back.Apply(PlanarCorrection{1.0, 0.0, 90 * kDeg}.Apply({2.0, -3.0}));
  EXPECT_NEAR(p.x(), 2.0, 1e-12);
  EXPECT_NEAR(p.y(), -3.0, 1e-12);
}

TEST(PlanarCorrectionTest, AfterAppliesTheOtherFirst) {
  // (0,0) -> shift by (1,0) -> turn 90 deg about the origin -> (0,1) -> shift by (1,0) -> (1,1).
  const PlanarCorrection turn{1.0, 0.0, 90 * kDeg};
  const PlanarCorrection shift{1.0, 0.0, 0.0};
  const PlanarCorrection both = turn.After(shift);
  EXPECT_NEAR(both.x, 1.0, 1e-12);
  EXPECT_NEAR(both.y, 1.0, 1e-12);
  EXPECT_NEAR(both.yaw, 90 * kDeg, 1e-12);
  const Eigen::Vector2d p = both.Apply({0.0, 0.0});
  EXPECT_NEAR(p.x(), 1.0, 1e-12);
  EXPECT_NEAR(p.y(), 1.0, 1e-12);
}

TEST(ScanMatcherTest, ACoarsePoseOffByDecimetresAndDegreesSnapsToTheWalls) {
  // The robot was carried off; its odometry believes a frame 3 m and 40 deg away. The landmark
  // answer is 0.2 m / -0.15 m and 6 deg off the truth, like the kidnapped bench's 3-5 object
  // answers; the walls bring it within a cell and a step.
  const PlanarCorrection truth{3.0, -1.0, 40 * kDeg};
  const PlanarCorrection coarse{truth.x + 0.2, truth.y - 0.15, truth.yaw + 6 * kDeg};
  absl::StatusOr<ScanMatchResult> result =
      MatchScan(Room(), ScanInReportedFrame(truth), coarse, ScanMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->refined);
  EXPECT_GT(result->score, 0.9);
  EXPECT_LT(result->coarse_score, 0.5);  // some walls still lie within a sigma or two
  // Compare where the correction takes the room's centre in the reported frame.
  const Eigen::Vector2d centre = truth.Inverse().Apply({3.5, 2.5});
  EXPECT_LT((result->correction.Apply(centre) - Eigen::Vector2d(3.5, 2.5)).norm(), 0.05);
  EXPECT_LT(std::abs(result->correction.yaw - truth.yaw), 0.75 * kDeg);
}

TEST(ScanMatcherTest, TheRightPoseStaysWhereItIs) {
  const PlanarCorrection truth{-2.0, 5.0, -120 * kDeg};
  absl::StatusOr<ScanMatchResult> result =
      MatchScan(Room(), ScanInReportedFrame(truth), truth, ScanMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->refined);  // nothing beats it by min_gain
  EXPECT_NEAR(result->correction.x, truth.x, 1e-12);
  EXPECT_NEAR(result->correction.y, truth.y, 1e-12);
  EXPECT_NEAR(result->correction.yaw, truth.yaw, 1e-12);
}

TEST(ScanMatcherTest, AScanOfAPlaceTheMapHasNotSeenKeepsTheCoarsePose) {
  // The same scan against a map that holds only a wall 10 m away: nothing scores min_score.
  OccupiedRaster far = Room();
  std::fill(far.occupied.begin(), far.occupied.end(), 0);
  for (int row = 0; row < far.height; ++row) far.occupied[static_cast<size_t>(row) * far.width] = 1;
  const PlanarCorrection coarse{10.0, 0.0, 0.0};
  absl::StatusOr<ScanMatchResult> result =
      MatchScan(far, ScanInReportedFrame({0.0, 0.0, 0.0}), coarse, ScanMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->refined);
  EXPECT_NEAR(result->correction.x, 10.0, 1e-12);
  EXPECT_LT(result->score, ScanMatchConfig{}.min_score);
}

TEST(ScanMatcherTest, AnEmptyMapKeepsTheCoarsePose) {
  OccupiedRaster empty = Room();
  std::fill(empty.occupied.begin(), empty.occupied.end(), 0);
  absl::StatusOr<ScanMatchResult> result =
      MatchScan(empty, ScanInReportedFrame({0.0, 0.0, 0.0}), {0.1, 0.0, 0.0}, ScanMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->refined);
  EXPECT_NEAR(result->correction.x, 0.1, 1e-12);
}

TEST(ScanMatcherTest, AScanOfAFewCellsIsRefused) {
  // 40 points on 10 cells (four per 5 cm cell): under min_scan_cells (30).
  std::vector<Eigen::Vector2d> scan;
  for (int i = 0; i < 40; ++i) scan.emplace_back(1.0 + 0.0125 * i + 0.001, 1.001);
  absl::StatusOr<ScanMatchResult> result = MatchScan(Room(), scan, {}, ScanMatchConfig{});
  EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(result.status().message().find("10 obstacle cells"), std::string::npos)
      << result.status();
}

TEST(ScanMatcherTest, ARasterWhoseCellsDoNotMatchItsSizeIsRefused) {
  OccupiedRaster bad = Room();
  bad.occupied.pop_back();
  EXPECT_EQ(MatchScan(bad, RoomPointsInMap(), {}, ScanMatchConfig{}).status().code(),
            absl::StatusCode::kInvalidArgument);
}

// The room's inside as observed free (the cabinet's footprint is not free).
OccupiedRaster WithFreeInside(OccupiedRaster map, bool cabinet) {
  map.observed_free.assign(map.occupied.size(), 0);
  for (int row = 0; row < map.height; ++row) {
    for (int col = 0; col < map.width; ++col) {
      const double x = (col + 0.5) * map.resolution;
      const double y = (row + 0.5) * map.resolution;
      const bool inside = x > 0.6 && x < 6.4 && y > 0.6 && y < 4.4;
      const bool under_cabinet = cabinet && x > 5.45 && y > 3.45;
      map.observed_free[static_cast<size_t>(row) * map.width + col] = inside && !under_cabinet;
    }
  }
  return map;
}

std::vector<Eigen::Vector2d> BareRoomPointsInMap() {
  std::vector<Eigen::Vector2d> points;
  for (double x = 0.52; x <= 6.48; x += 0.02) {
    points.emplace_back(x, 4.52);
    points.emplace_back(x, 0.52);
  }
  for (double y = 0.52; y <= 4.48; y += 0.02) {
    points.emplace_back(0.52, y);
    points.emplace_back(6.48, y);
  }
  return points;
}

TEST(GlobalScanMatcherTest, ALostRobotIsFoundAnywhereAtAnyHeading) {
  // Carried 5 m and 120 deg from where it believes it is; no coarse pose at all.
  const PlanarCorrection truth{5.0, -3.0, 120 * kDeg};
  const Eigen::Vector2d robot_in_map(2.0, 2.5);
  const Eigen::Vector2d robot_reported = truth.Inverse().Apply(robot_in_map);
  absl::StatusOr<ScanMatchResult> result =
      MatchScanGlobally(WithFreeInside(Room(), true), ScanInReportedFrame(truth), robot_reported,
                        ScanMatchConfig{}, GlobalMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->refined) << result->score << " vs " << result->runner_up_score;
  EXPECT_GT(result->score, 0.9);
  // The half turn fits all but the cabinet: twice the best pose's unexplained cells.
  EXPECT_GT(1.0 - result->runner_up_score, 1.5 * (1.0 - result->score));
  EXPECT_LT((result->correction.Apply(robot_reported) - robot_in_map).norm(), 0.08);
  EXPECT_LT(std::abs(std::remainder(result->correction.yaw - truth.yaw, 2 * M_PI)), 1.0 * kDeg);
}

TEST(GlobalScanMatcherTest, ARoomThatLooksTheSameAfterAHalfTurnIsNoAnswer) {
  // The room without its cabinet, a bare rectangle: the robot at (2, 2.5) facing one way sees
  // what a robot at (5, 2.5) facing the other way sees. Both poses score alike, so neither is
  // taken.
  const PlanarCorrection truth{5.0, -3.0, 120 * kDeg};
  const PlanarCorrection reported_from_map = truth.Inverse();
  std::vector<Eigen::Vector2d> scan;
  for (const Eigen::Vector2d& p : BareRoomPointsInMap()) scan.push_back(reported_from_map.Apply(p));
  const Eigen::Vector2d robot_reported = reported_from_map.Apply({2.0, 2.5});
  absl::StatusOr<ScanMatchResult> result =
      MatchScanGlobally(WithFreeInside(Room(/*cabinet=*/false), false), scan, robot_reported,
                        ScanMatchConfig{}, GlobalMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_GT(result->score, 0.9);
  EXPECT_GT(result->runner_up_score, result->score - 0.02);
  EXPECT_FALSE(result->refined);
}

TEST(GlobalScanMatcherTest, ThePoseTheRobotReportsIsNeverTheAnswer) {
  // Its own frames from before it reported the loss may have drawn what it sees where it
  // believes it is: that pose (the identity correction) is no answer, but it competes, so the
  // half-turn look-alike elsewhere is not taken either.
  const Eigen::Vector2d robot(2.0, 2.5);
  absl::StatusOr<ScanMatchResult> result =
      MatchScanGlobally(WithFreeInside(Room(), true), ScanInReportedFrame({0.0, 0.0, 0.0}), robot,
                        ScanMatchConfig{}, GlobalMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->refined);
  EXPECT_GT(
      std::hypot(result->correction.x, result->correction.y) + std::abs(result->correction.yaw),
      0.09);
}

TEST(GlobalScanMatcherTest, AnAnswerWhoseRaysCrossTheMapsWallsIsNoAnswer) {
  // The map has a wall across the room at x = 4 that the scan sees through: the walls beyond it
  // fit, but no robot at (2, 2.5) could have seen them. Over a third of the rays cross it.
  OccupiedRaster divided = WithFreeInside(Room(), true);
  for (double y = 0.5; y <= 4.5; y += 0.025) {
    divided.occupied[static_cast<size_t>(std::floor(y / divided.resolution)) * divided.width +
                     static_cast<size_t>(std::floor(4.0 / divided.resolution))] = 1;
  }
  const PlanarCorrection truth{5.0, -3.0, 120 * kDeg};
  const Eigen::Vector2d robot_reported = truth.Inverse().Apply({2.0, 2.5});
  absl::StatusOr<ScanMatchResult> result = MatchScanGlobally(
      divided, ScanInReportedFrame(truth), robot_reported, ScanMatchConfig{}, GlobalMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_GT(result->ray_conflicts, 0.3);
  EXPECT_FALSE(result->refined);
  // Without the divider the same answer crosses nothing (the first test's case).
  result = MatchScanGlobally(WithFreeInside(Room(), true), ScanInReportedFrame(truth),
                             robot_reported, ScanMatchConfig{}, GlobalMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_LT(result->ray_conflicts, 0.01);
  EXPECT_TRUE(result->refined);
}

TEST(GlobalScanMatcherTest, RaysThatGrazeTheWallTheRobotStandsByStillFindIt) {
  // The robot stands 15 cm from the room's long wall. Its rays to that wall's far points run
  // along the wall's cells for their last metres: they meet it, but never come out beyond it.
  const PlanarCorrection truth{5.0, -3.0, 120 * kDeg};
  const Eigen::Vector2d robot_in_map(3.0, 0.65);
  const Eigen::Vector2d robot_reported = truth.Inverse().Apply(robot_in_map);
  GlobalMatchConfig any_wall_met;
  any_wall_met.ray_emerge_cells = 0;  // every wall met counts (the rule before 2026-12-01)
  absl::StatusOr<ScanMatchResult> result =
      MatchScanGlobally(WithFreeInside(Room(), true), ScanInReportedFrame(truth), robot_reported,
                        ScanMatchConfig{}, any_wall_met);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_GT(result->ray_conflicts, 0.1);
  EXPECT_FALSE(result->refined);
  result = MatchScanGlobally(WithFreeInside(Room(), true), ScanInReportedFrame(truth),
                             robot_reported, ScanMatchConfig{}, GlobalMatchConfig{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_LT(result->ray_conflicts, 0.02);
  EXPECT_TRUE(result->refined) << result->score << " vs " << result->runner_up_score;
  EXPECT_LT((result->correction.Apply(robot_reported) - robot_in_map).norm(), 0.08);
}

}  // namespace
}  // namespace semnav::mapping
