// The hierarchical grid of a real building: the FR-079 corridor OctoMap (0.08 m, Uni Freiburg).
#include <gtest/gtest.h>

#include <queue>

#include "services/mapping/core/grid_layers.h"

namespace semnav::mapping {
namespace {

class Fr079GridTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const octomap::OcTree tree(std::string(SEMNAV_SHARED_DATA_DIR) +
                               "/pointclouds-octomaps/octomap_share/geb079.bt");
    ASSERT_GT(tree.size(), 0u);
    const VoxelColumns columns = VoxelColumns::FromOctree(tree);
    heights_ = new ClimbingHeights(*EstimateHeights(columns));
    HierarchicalGridConfig config;
    config.resolution_m = 0.04;
    grid_ = new HierarchicalGrid(config, *heights_);
    absl::flat_hash_set<VoxelColumns::ColumnId> all;
    for (const auto& [id, column] : columns.columns()) all.insert(id);
    grid_->Update(columns, all);
  }
  static void TearDownTestSuite() {
    delete grid_;
    delete heights_;
  }
  static HierarchicalGrid* grid_;
  static ClimbingHeights* heights_;
};

HierarchicalGrid* Fr079GridTest::grid_ = nullptr;
ClimbingHeights* Fr079GridTest::heights_ = nullptr;

TEST_F(Fr079GridTest, EstimatesFloorAndCeilingOfTheCorridor) {
  // Occupied-voxel peaks: floor at z = -0.04 m, ceiling at z = 2.68 m (0.08 m voxel centres).
  EXPECT_NEAR(heights_->foot_m, 0.04, 1e-6);
  EXPECT_NEAR(heights_->ceiling_m, 2.60, 1e-6);
}

TEST_F(Fr079GridTest, CorridorWallsAreStructure) {
  // Along the corridor (x = -6 .. 28 m) most 0.5 m stations have a structure cell in each wall
  // band; the rest are doors.
  for (double band : {-1.6, 1.0}) {
    int stations = 0;
    int with_wall = 0;
    for (double x = -6.0; x <= 28.0; x += 0.5) {
      bool wall = false;
      for (double y = band; y <= band + 0.6; y += 0.02)
        wall = wall || grid_->Value(grid_->CellOf(x, y)) == 100;
      ++stations;
      with_wall += wall ? 1 : 0;
    }
    EXPECT_GE(with_wall, stations / 2) << "wall band starting at y = " << band;
  }
}

TEST_F(Fr079GridTest, CorridorIsFreeAndConnectedEndToEnd) {
  const GridWindow window = FullWindow(*grid_);
  const GridLayers layers = RenderLayers(*grid_, window, GridLayersConfig{});
  auto cell_of = [&](double x, double y) {
    const CellIndex c = grid_->CellOf(x, y);
    return std::pair<int, int>{c.x - window.min.x, c.y - window.min.y};
  };
  auto free_at = [&](int col, int row) {
    return col >= 0 && row >= 0 && col < layers.width && row < layers.height &&
           layers.hierarchical[static_cast<size_t>(row) * layers.width + col] == 0;
  };
  const auto [start_col, start_row] = cell_of(-6.0, 0.3);
  const auto [goal_col, goal_row] = cell_of(27.5, 0.3);
  ASSERT_TRUE(free_at(start_col, start_row));
  ASSERT_TRUE(free_at(goal_col, goal_row));
  std::vector<uint8_t> seen(layers.hierarchical.size(), 0);
  std::queue<std::pair<int, int>> open;
  open.push({start_col, start_row});
  seen[static_cast<size_t>(start_row) * layers.width + start_col] = 1;
  bool reached = false;
  while (!open.empty() && !reached) {
    const auto [col, row] = open.front();
    open.pop();
    reached = col == goal_col && row == goal_row;
    for (const auto& [dc, dr] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int c = col + dc;
      const int r = row + dr;
      if (!free_at(c, r) || seen[static_cast<size_t>(r) * layers.width + c] != 0) continue;
      seen[static_cast<size_t>(r) * layers.width + c] = 1;
      open.push({c, r});
    }
  }
  EXPECT_TRUE(reached);
  // Sanity on the straight line itself: free at every 0.5 m station.
  int free_stations = 0;
  for (double x = -6.0; x <= 28.0; x += 0.5)
    free_stations += grid_->Value(grid_->CellOf(x, 0.3)) == 0 ? 1 : 0;
  EXPECT_GE(free_stations, 68);  // of 69
}

}  // namespace
}  // namespace semnav::mapping
