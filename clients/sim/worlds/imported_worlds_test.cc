// Worlds made from the real data in shared/data: HouseExpo plans and the FR-079 OctoMap.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "clients/sim/core/scene.h"
#include "clients/sim/core/world_yaml.h"
#include "clients/sim/worlds/houseexpo_world.h"
#include "clients/sim/worlds/octomap_world.h"
#include "clients/sim/worlds/start_poses.h"

namespace semnav::sim {
namespace {

const std::string kData = SEMNAV_SHARED_DATA_DIR;

void ExpectStartsFree(const World& world) {
  const Scene scene = Scene::Build(world);
  ASSERT_EQ(world.starts.size(), 5u);
  for (const StartPose& s : world.starts) {
    EXPECT_FALSE(scene.SolidTouchingCylinder(s.position.head<2>(), 0.25, 0.05, 0.6).has_value());
  }
}

TEST(SimHouseExpoWorldTest, PlanZeroBecomesWallsRoomsAndObjects) {
  const auto world =
      HouseExpoWorld(kData + "/floorplans/houseexpo_samples/house_expo_room_0000.json", "he0", 1);
  ASSERT_TRUE(world.ok()) << world.status();
  // 147 outline vertices -> 147 wall boxes; three labelled room boxes (SOURCE.txt).
  EXPECT_EQ(
      world->obstacles.size() -
          [&] {
            size_t furniture = 0;
            for (const Obstacle& o : world->obstacles) furniture += o.kind == "furniture" ? 1 : 0;
            return furniture;
          }(),
      147u);
  ASSERT_EQ(world->rooms.size(), 3u);
  EXPECT_EQ(world->rooms[0].type, "bedroom");  // JSON key order: Bedroom, Room, Storage
  EXPECT_FALSE(world->objects.empty());
  ExpectStartsFree(*world);
}

TEST(SimHouseExpoWorldTest, DuplicateRoomBoxesAndErrors) {
  const auto world = HouseExpoWorld(
      kData + "/floorplans/houseexpo_samples/house_expo_room_1451.json", "he1451", 1);
  ASSERT_TRUE(world.ok()) << world.status();
  // 8 boxes listed; Toilet and Bathroom share one box, kept once.
  EXPECT_EQ(world->rooms.size(), 7u);
  EXPECT_EQ(HouseExpoWorld("/nonexistent.json", "x", 1).status().code(),
            absl::StatusCode::kNotFound);
  const std::string bad = ::testing::TempDir() + "/bad_plan.json";
  std::ofstream(bad) << R"({"verts": [[0, 0], [1, 0]], "room_category": {}})";
  const auto error = HouseExpoWorld(bad, "x", 1);
  EXPECT_EQ(error.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(std::string(error.status().message()).find("houseexpo.verts"), std::string::npos);
}

TEST(SimOctomapWorldTest, Fr079VoxelsMergeIntoBoxes) {
  OctomapImport stats;
  const auto world =
      OctomapWorld(kData + "/pointclouds-octomaps/octomap_share/geb079.bt", "fr079", 1, &stats);
  ASSERT_TRUE(world.ok()) << world.status();
  // SOURCE.txt: 0.08 m resolution, x -8.00..30.96, y -7.52..7.44.
  EXPECT_NEAR(world->bounds_min.x(), -8.0, 0.1);
  EXPECT_NEAR(world->bounds_max.x(), 30.96, 0.1);
  EXPECT_GT(stats.occupied_voxels, 10000);
  EXPECT_LT(stats.boxes, stats.occupied_voxels / 3);  // merging pays off
  EXPECT_GE(world->objects.size(), 5u);
  ExpectStartsFree(*world);
  EXPECT_EQ(OctomapWorld("/nonexistent.bt", "x", 1).status().code(), absl::StatusCode::kNotFound);
}

// Regression: the scan's outside was free, so the robot's region (where every start and object
// is drawn) ran round the outside of the building from room to room, and the corridor was out
// of reach. Now the region stays inside: none of it lies on the edge of the bounds, and it spans
// the corridor, the building's long axis (x -8..31, SOURCE.txt).
TEST(SimOctomapWorldTest, Fr079RobotsStayInsideTheScannedBuilding) {
  const auto world =
      OctomapWorld(kData + "/pointclouds-octomaps/octomap_share/geb079.bt", "fr079", 1);
  ASSERT_TRUE(world.ok()) << world.status();
  // The walls that close it lie within the bounds, as a world file's must.
  const absl::StatusOr<World> reloaded = ParseWorldYaml(WorldToYaml(*world));
  EXPECT_TRUE(reloaded.ok()) << reloaded.status();
  const GroundTruthGrid grid = ModalityGrid(*world, Modality::kGround, 0.0);
  const std::vector<uint8_t> region = LargestFreeRegion(grid);
  for (int x = 0; x < grid.width; ++x) {
    for (const int y : {0, grid.height - 1}) {
      EXPECT_EQ(region[static_cast<size_t>(y) * grid.width + x], 0) << x << ", " << y;
    }
  }
  for (int y = 0; y < grid.height; ++y) {
    for (const int x : {0, grid.width - 1}) {
      EXPECT_EQ(region[static_cast<size_t>(y) * grid.width + x], 0) << x << ", " << y;
    }
  }
  // The corridor runs the length of the building: the region spans it.
  int min_x = grid.width, max_x = -1;
  for (size_t i = 0; i < region.size(); ++i) {
    if (region[i] == 0) continue;
    min_x = std::min(min_x, static_cast<int>(i % grid.width));
    max_x = std::max(max_x, static_cast<int>(i % grid.width));
  }
  EXPECT_LT(grid.origin.x() + min_x * grid.resolution, 0.0);
  EXPECT_GT(grid.origin.x() + max_x * grid.resolution, 25.0);
}

}  // namespace
}  // namespace semnav::sim
