#include "services/mapping/core/climbing.h"

#include <gtest/gtest.h>

namespace semnav::mapping {
namespace {

constexpr double kRes = 0.1;

// Fills voxel column (x key 100, y key 100) from z = from_m to to_m (centres) with `state`.
void Fill(VoxelColumns& columns, double from_m, double to_m, VoxelState state) {
  for (int z = columns.CoordToKey(from_m); z <= columns.CoordToKey(to_m); ++z) {
    columns.Set(octomap::OcTreeKey(100, 100, static_cast<octomap::key_type>(z)), state);
  }
}

const VoxelColumns::ColumnId kColumn = VoxelColumns::IdOf(100, 100);
const ClimbingHeights kHeights{0.15, 2.05};  // foot voxel 0.1-0.2, ceiling voxel 2.0-2.1

TEST(ClimbingTest, ColumnOccupiedFromFootToCeilingIsStructure) {
  VoxelColumns columns(kRes);
  Fill(columns, 0.05, 2.45, VoxelState::kOccupied);
  EXPECT_EQ(ClimbColumn(columns, kColumn, kHeights).kind, ColumnClass::kStructure);
}

TEST(ClimbingTest, LowBoxIsObstacleWithItsTopHeight) {
  VoxelColumns columns(kRes);
  Fill(columns, 0.05, 2.45, VoxelState::kFree);
  Fill(columns, 0.05, 0.75, VoxelState::kOccupied);
  const ColumnResult result = ClimbColumn(columns, kColumn, kHeights);
  EXPECT_EQ(result.kind, ColumnClass::kObstacle);
  EXPECT_NEAR(result.top_m, 0.75, 1e-9);
}

TEST(ClimbingTest, VoxelsNotConnectedToFootAreIgnored) {
  VoxelColumns columns(kRes);
  Fill(columns, 0.05, 2.45, VoxelState::kFree);
  Fill(columns, 1.75, 1.85, VoxelState::kOccupied);  // a lamp hanging at 1.8 m
  EXPECT_EQ(ClimbColumn(columns, kColumn, kHeights).kind, ColumnClass::kFree);
}

TEST(ClimbingTest, ClimbCrossesUnobservedVoxelsButNotFreeOnes) {
  VoxelColumns columns(kRes);
  Fill(columns, 0.05, 2.45, VoxelState::kOccupied);
  Fill(columns, 1.05, 1.25, VoxelState::kUnknown);  // a hole the sensor never saw into
  EXPECT_EQ(ClimbColumn(columns, kColumn, kHeights).kind, ColumnClass::kStructure);
  Fill(columns, 1.15, 1.15, VoxelState::kFree);
  const ColumnResult result = ClimbColumn(columns, kColumn, kHeights);
  EXPECT_EQ(result.kind, ColumnClass::kObstacle);
  EXPECT_NEAR(result.top_m, 0.95, 1e-9);
}

TEST(ClimbingTest, VoxelHangingWithinTheBodyBlocksAndOneAboveItDoesNot) {
  // kHeights' foot voxel is 0.1-0.2 m; a 0.5 m body reaches the voxel of 0.65 m (0.6-0.7 m).
  ClimbingHeights body = kHeights;
  body.body_m = 0.5;
  VoxelColumns columns(kRes);
  Fill(columns, 0.05, 2.45, VoxelState::kFree);
  Fill(columns, 0.45, 0.45, VoxelState::kOccupied);  // a chair seat at 0.4-0.5 m, legs unseen
  EXPECT_EQ(ClimbColumn(columns, kColumn, kHeights).kind, ColumnClass::kFree);  // the seed's
  ColumnResult result = ClimbColumn(columns, kColumn, body);
  EXPECT_EQ(result.kind, ColumnClass::kObstacle);
  EXPECT_NEAR(result.top_m, 0.45, 1e-9);
  // A low box from the foot and a seat above it: the top is the seat's.
  Fill(columns, 0.15, 0.25, VoxelState::kOccupied);
  result = ClimbColumn(columns, kColumn, body);
  EXPECT_EQ(result.kind, ColumnClass::kObstacle);
  EXPECT_NEAR(result.top_m, 0.45, 1e-9);
  // A lamp at 0.75 m hangs above the 0.65 m voxel: ignored, as in the seed.
  VoxelColumns lamp(kRes);
  Fill(lamp, 0.05, 2.45, VoxelState::kFree);
  Fill(lamp, 0.75, 0.75, VoxelState::kOccupied);
  EXPECT_EQ(ClimbColumn(lamp, kColumn, body).kind, ColumnClass::kFree);
  Fill(lamp, 0.65, 0.65, VoxelState::kOccupied);
  EXPECT_EQ(ClimbColumn(lamp, kColumn, body).kind, ColumnClass::kObstacle);
}

TEST(ClimbingTest, RunHangingFromCeilingIsIgnored) {
  VoxelColumns columns(kRes);
  Fill(columns, 0.05, 2.45, VoxelState::kFree);
  Fill(columns, 1.85, 2.45, VoxelState::kOccupied);  // a lintel over a door
  EXPECT_EQ(ClimbColumn(columns, kColumn, kHeights).kind, ColumnClass::kFree);
}

TEST(ClimbingTest, SolidBoxSeenFromOutsideIsObstacle) {
  VoxelColumns columns(kRes);
  Fill(columns, 0.05, 0.05, VoxelState::kOccupied);  // floor
  Fill(columns, 0.75, 0.75, VoxelState::kOccupied);  // box top face; inside never observed
  Fill(columns, 0.85, 2.45, VoxelState::kFree);
  const ColumnResult result = ClimbColumn(columns, kColumn, kHeights);
  EXPECT_EQ(result.kind, ColumnClass::kObstacle);
  EXPECT_NEAR(result.top_m, 0.75, 1e-9);
}

TEST(ClimbingTest, UnseenColumnIsUnknown) {
  const VoxelColumns columns(kRes);
  EXPECT_EQ(ClimbColumn(columns, kColumn, kHeights).kind, ColumnClass::kUnknown);
}

TEST(ClimbingTest, EstimatesFootAboveFloorAndCeilingBelowRoof) {
  VoxelColumns columns(kRes);
  for (int x = 0; x < 20; ++x) {
    for (int y = 0; y < 20; ++y) {
      const auto kx = static_cast<octomap::key_type>(200 + x);
      const auto ky = static_cast<octomap::key_type>(200 + y);
      columns.Set(
          octomap::OcTreeKey(kx, ky, static_cast<octomap::key_type>(columns.CoordToKey(0.05))),
          VoxelState::kOccupied);
      columns.Set(
          octomap::OcTreeKey(kx, ky, static_cast<octomap::key_type>(columns.CoordToKey(2.55))),
          VoxelState::kOccupied);
    }
  }
  Fill(columns, 0.05, 2.55, VoxelState::kOccupied);  // one wall column does not move the peaks
  const std::optional<ClimbingHeights> heights = EstimateHeights(columns);
  ASSERT_TRUE(heights.has_value());
  EXPECT_NEAR(heights->foot_m, 0.15, 1e-9);
  EXPECT_NEAR(heights->ceiling_m, 2.45, 1e-9);
}

}  // namespace
}  // namespace semnav::mapping
