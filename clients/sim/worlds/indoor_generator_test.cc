#include "clients/sim/worlds/indoor_generator.h"

#include <gtest/gtest.h>

#include <set>

#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/world_yaml.h"
#include "clients/sim/worlds/room_object_table.h"
#include "clients/sim/worlds/start_poses.h"

namespace semnav::sim {
namespace {

TEST(SimIndoorGeneratorTest, SameSeedSameWorldDifferentSeedDifferentWorld) {
  IndoorOptions options;
  const std::string a = WorldToYaml(GenerateIndoor("home", options, 3));
  EXPECT_EQ(a, WorldToYaml(GenerateIndoor("home", options, 3)));
  EXPECT_NE(a, WorldToYaml(GenerateIndoor("home", options, 4)));
}

class SimIndoorWorldsTest : public ::testing::TestWithParam<std::tuple<Building, uint64_t>> {};

TEST_P(SimIndoorWorldsTest, EveryRoomReachableFurnishedAndStartsFree) {
  IndoorOptions options;
  options.building = std::get<0>(GetParam());
  const World world = GenerateIndoor("w", options, std::get<1>(GetParam()));
  ASSERT_GE(world.rooms.size(), 3u);
  ASSERT_EQ(world.starts.size(), 5u);
  // Doors connect every room: each has cells in the one largest free region.
  const GroundTruthGrid grid = ModalityGrid(world, Modality::kGround, 0.0);
  const std::vector<uint8_t> region = LargestFreeRegion(grid);
  for (const Room& room : world.rooms) {
    bool reached = false;
    for (int y = 0; y < grid.height && !reached; ++y) {
      for (int x = 0; x < grid.width && !reached; ++x) {
        const Eigen::Vector2d c = grid.origin + grid.resolution * Eigen::Vector2d(x + 0.5, y + 0.5);
        reached =
            region[static_cast<size_t>(y) * grid.width + x] && PointInPolygon(room.polygon, c);
      }
    }
    EXPECT_TRUE(reached) << room.name;
  }
  // Objects come from the room-object table of their room's type, inside that room.
  std::set<std::string> labels;
  for (const ObjectInstance& o : world.objects) {
    const Room* room = nullptr;
    for (const Room& r : world.rooms) room = r.name == o.room ? &r : room;
    ASSERT_NE(room, nullptr) << o.id;
    bool listed = false;
    for (const ItemSpec& item : RoomItems(room->type)) listed = listed || item.label == o.label;
    EXPECT_TRUE(listed) << o.label << " in " << room->type;
    EXPECT_TRUE(PointInPolygon(room->polygon, o.box.center)) << o.id;
    labels.insert(o.label);
  }
  EXPECT_GE(labels.size(), 5u);
  World copy = world;
  EXPECT_EQ(RemoveUnreachableObjects(copy, Modality::kGround, 0.0), 0);
  const Scene scene = Scene::Build(world);
  // Starts keep a margin beyond the 0.25 m radius, so the first move cannot graze anything.
  for (const StartPose& s : world.starts) {
    EXPECT_FALSE(scene.SolidTouchingCylinder(s.position.head<2>(), 0.28, 0.05, 0.6).has_value());
  }
}

INSTANTIATE_TEST_SUITE_P(SimSeeds, SimIndoorWorldsTest,
                         ::testing::Combine(::testing::Values(Building::kHome, Building::kOffice),
                                            ::testing::Values(1u, 2u, 3u)));

}  // namespace
}  // namespace semnav::sim
