#include "services/mapping/core/hierarchical_grid.h"

#include <gtest/gtest.h>

namespace semnav::mapping {
namespace {

const ClimbingHeights kHeights{0.15, 2.05};

// A 0.1 m voxel column at (x, y) keys with free voxels from floor to ceiling and an optional
// box from the floor up to box_top_m.
void SetColumn(VoxelColumns& columns, int x, int y, double box_top_m) {
  for (int z = columns.CoordToKey(0.05); z <= columns.CoordToKey(2.45); ++z) {
    const bool box = columns.KeyToCoord(z) <= box_top_m;
    columns.Set(
        octomap::OcTreeKey(static_cast<octomap::key_type>(x), static_cast<octomap::key_type>(y),
                           static_cast<octomap::key_type>(z)),
        box ? VoxelState::kOccupied : VoxelState::kFree);
  }
}

TEST(HierarchicalGridTest, CoverageFollowsEquations1And2) {
  HierarchicalGridConfig config;
  config.resolution_m = 0.05;
  const HierarchicalGrid grid(config, kHeights);
  // R_o = 0.2, R_g = 0.05: m in [-2, 2] around floor(1.1 / 0.05) = 22.
  EXPECT_EQ(grid.CoveredCells(1.1, 0.2), (std::vector<int>{20, 21, 22, 23, 24}));
  // R_o = R_g: m in [-0.5, 0.5] -> only m = 0.
  EXPECT_EQ(grid.CoveredCells(1.125, 0.05), (std::vector<int>{22}));
}

TEST(HierarchicalGridTest, HeightValueFollowsEquation3) {
  const HierarchicalGrid grid(HierarchicalGridConfig{}, ClimbingHeights{0.1, 2.1});
  EXPECT_EQ(grid.HeightValue(1.1), 50);
  EXPECT_EQ(grid.HeightValue(0.6), 25);
  EXPECT_EQ(grid.HeightValue(0.1), 1);   // never 0 (free)
  EXPECT_EQ(grid.HeightValue(2.1), 99);  // never 100 (structure)
}

TEST(HierarchicalGridTest, BayesUpdateFollowsEquations6To9) {
  HierarchicalGridConfig config;
  config.resolution_m = 0.1;
  HierarchicalGrid grid(config, kHeights);
  VoxelColumns columns(0.1);
  const int kx = columns.CoordToKey(1.05);
  const int ky = columns.CoordToKey(1.05);
  const absl::flat_hash_set<VoxelColumns::ColumnId> observed{VoxelColumns::IdOf(kx, ky)};
  const CellIndex cell = grid.CellOf(1.05, 1.05);
  EXPECT_EQ(grid.Value(cell), HierarchicalGrid::kUnknown);

  SetColumn(columns, kx, ky, 1.0);  // box top voxel centre 0.95 m
  grid.Update(columns, observed);
  // L = logit(0.7) = 0.847, p = 0.7 >= 0.65: h_o = 100 (0.95 - 0.15) / 1.9 = 42.
  EXPECT_NEAR(grid.Probability(cell), 0.7, 1e-6);
  EXPECT_EQ(grid.Value(cell), 42);

  SetColumn(columns, kx, ky, 0.0);  // the box left
  grid.Update(columns, observed);
  // L = 0.847 + logit(0.4) = 0.442, p = 0.609 < 0.65: free.
  EXPECT_NEAR(grid.Probability(cell), 0.6087, 1e-4);
  EXPECT_EQ(grid.Value(cell), HierarchicalGrid::kFree);
}

TEST(HierarchicalGridTest, StructureColumnIsHundred) {
  HierarchicalGridConfig config;
  config.resolution_m = 0.1;
  HierarchicalGrid grid(config, kHeights);
  VoxelColumns columns(0.1);
  SetColumn(columns, 40000, 40000, 3.0);
  grid.Update(columns, {VoxelColumns::IdOf(40000, 40000)});
  EXPECT_EQ(grid.Value(grid.CellOf(columns.KeyToCoord(40000), columns.KeyToCoord(40000))),
            HierarchicalGrid::kStructure);
}

}  // namespace
}  // namespace semnav::mapping
