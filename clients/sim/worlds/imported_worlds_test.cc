// Worlds made from the real data in shared/data: HouseExpo plans and the FR-079 OctoMap.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "clients/sim/core/scene.h"
#include "clients/sim/worlds/houseexpo_world.h"
#include "clients/sim/worlds/octomap_world.h"

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

}  // namespace
}  // namespace semnav::sim
