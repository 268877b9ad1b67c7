#include "services/mapping/core/scan_matcher.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::mapping {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A 6 x 4 m room (walls one cell thick) with a 1 x 1 m cabinet in one corner, at 5 cm cells,
// origin (0, 0).
OccupiedRaster Room() {
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
  for (double t = 5.5; t <= 6.5; t += 0.025) {
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

PlanarCorrection Inverse(const PlanarCorrection& t) {
  const double c = std::cos(-t.yaw);
  const double s = std::sin(-t.yaw);
  return {-(c * t.x - s * t.y), -(s * t.x + c * t.y), -t.yaw};
}

// The robot's reported frame: `truth` takes it to the map.
std::vector<Eigen::Vector2d> ScanInReportedFrame(const PlanarCorrection& truth) {
  const PlanarCorrection reported_from_map = Inverse(truth);
  std::vector<Eigen::Vector2d> scan;
  for (const Eigen::Vector2d& p : RoomPointsInMap()) scan.push_back(reported_from_map.Apply(p));
  return scan;
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
  const Eigen::Vector2d centre = Inverse(truth).Apply({3.5, 2.5});
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

}  // namespace
}  // namespace semnav::mapping
