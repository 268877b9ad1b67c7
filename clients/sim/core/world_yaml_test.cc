#include "clients/sim/core/world_yaml.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "services/common/status/field_error.h"

namespace semnav::sim {
namespace {

constexpr char kWorld[] = R"(
name: tiny
bounds: {min: [-0.1, -0.1], max: [6, 4]}
ceiling_height: 2.5
rooms:
  - {name: kitchen_1, type: kitchen, polygon: [[0, 0], [6, 0], [6, 4], [0, 4]]}
starts:
  - {position: [1, 1, 0], yaw: 0.5, modality: ground}
objects:
  - {id: fridge_1, label: refrigerator, colour: [240, 240, 240], room: kitchen_1,
     box: {center: [5, 3], size: [0.7, 0.7, 1.8]}}
obstacles:
  - {kind: wall, colour: [200, 200, 200], box: {center: [3, 0], size: [6, 0.1, 2.5]}}
  - {kind: furniture, prism: {polygon: [[1, 2], [2, 2], [2, 3]], height: 0.9}}
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

void ExpectInvalid(const std::string& text, const std::string& field) {
  const absl::StatusOr<World> world = ParseWorldYaml(text);
  ASSERT_FALSE(world.ok()) << field;
  EXPECT_EQ(world.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(std::string(world.status().message()).find(field), std::string::npos)
      << world.status().message();
}

// The field travels as the status payload too (field_error.h), exactly.
void ExpectInvalidField(const std::string& text, const std::string& field) {
  const absl::StatusOr<World> world = ParseWorldYaml(text);
  ASSERT_FALSE(world.ok()) << field;
  EXPECT_EQ(world.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(world.status()), field) << world.status();
}

TEST(SimWorldYamlTest, ParsesEveryField) {
  const absl::StatusOr<World> world = ParseWorldYaml(kWorld);
  ASSERT_TRUE(world.ok()) << world.status();
  EXPECT_EQ(world->name, "tiny");
  EXPECT_DOUBLE_EQ(world->ceiling_height, 2.5);
  ASSERT_EQ(world->objects.size(), 1u);
  EXPECT_EQ(world->objects[0].label, "refrigerator");
  EXPECT_EQ(world->objects[0].room, "kitchen_1");
  EXPECT_DOUBLE_EQ(world->objects[0].box.size.z(), 1.8);
  ASSERT_EQ(world->obstacles.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<PrismShape>(world->obstacles[1].shape));
  EXPECT_EQ(world->starts[0].modality, Modality::kGround);
  EXPECT_DOUBLE_EQ(world->starts[0].yaw, 0.5);
}

TEST(SimWorldYamlTest, ErrorsNameTheField) {
  ExpectInvalid(Replace(kWorld, "size: [0.7, 0.7, 1.8]", "size: [0.7, 1.8]"),
                "objects[0].box.size");
  ExpectInvalid(Replace(kWorld, "modality: ground", "modality: boat"), "starts[0].modality");
  ExpectInvalid(Replace(kWorld, "kind: furniture,", "kind: furniture, colr: [1, 2, 3],"),
                "obstacles[1].colr");
  ExpectInvalid(Replace(kWorld, "room: kitchen_1,", "room: garage,"), "objects[0].room");
  ExpectInvalid(Replace(kWorld, "height: 0.9", "height: -1"), "obstacles[1].prism.height");
  ExpectInvalid(Replace(kWorld, "max: [6, 4]", "max: [-0.2, 4]"), "bounds.max");
  ExpectInvalid(Replace(kWorld, "colour: [240, 240, 240]", "colour: [240, 256, 240]"),
                "objects[0].colour");
  ExpectInvalid(Replace(kWorld, "name: tiny", "title: tiny"), "title");
  ExpectInvalid(Replace(kWorld, ", modality: ground", ""), "starts[0].modality: missing");
  ExpectInvalid(Replace(kWorld, "max: [6, 4]", "max: [6, .inf]"),
                "bounds.max[1]: expected a finite number");
  ExpectInvalid(Replace(kWorld, "[[1, 2], [2, 2], [2, 3]]", "[[1, 2], [2, 2], [2]]"),
                "obstacles[1].prism.polygon[2]: expected a list of 2 numbers");
  ExpectInvalid(Replace(kWorld, "prism: {", "box: {center: [1, 1], size: [1, 1, 1]}, prism: {"),
                "obstacles[1].prism: give either box or prism, not both");
  ExpectInvalid("name: [unclosed", "world: yaml-cpp: error at line 1");
}

// A world file is data: a key written without a value is an error, not "use the default" as in
// a service config (ConfigReaderOptions::null_is_absent).
TEST(SimWorldYamlTest, KeysWithoutAValueAreErrors) {
  ExpectInvalid(Replace(kWorld, "yaw: 0.5", "yaw: ~"), "starts[0].yaw: has no value");
  ExpectInvalid(Replace(kWorld, "room: kitchen_1,", "room: ~,"), "objects[0].room: has no value");
  ExpectInvalid(Replace(kWorld, "ceiling_height: 2.5", "ceiling_height:"),
                "ceiling_height: has no value");
  ExpectInvalid(Replace(kWorld, "box: {center: [5, 3], size: [0.7, 0.7, 1.8]}", "box: ~"),
                "objects[0].box: has no value");
  ExpectInvalid(Replace(kWorld, "  - {kind: furniture,", "  - ~\n  - {kind: furniture,"),
                "obstacles[1]: must be a mapping");
}

// Every world drawn by hand for the benchmarks (docs/simulation.md) passes the loader.
TEST(SimWorldYamlTest, HandDrawnWorldsLoad) {
  const auto suite = LoadSuite(SEMNAV_SOURCE_DIR "/tests/worlds/hand_drawn");
  ASSERT_TRUE(suite.ok()) << suite.status();
  ASSERT_EQ(suite->size(), 6u);
  EXPECT_EQ(suite->front().name, "clinic");
  EXPECT_EQ(suite->back().name, "yard_parking");
}

TEST(SimWorldYamlTest, HandDrawnHoldoutWorldsLoad) {
  // Drawn by another hand and never tuned on: only a check that the strategy generalises.
  const auto suite = LoadSuite(SEMNAV_SOURCE_DIR "/tests/worlds/hand_drawn_holdout");
  ASSERT_TRUE(suite.ok()) << suite.status();
  ASSERT_EQ(suite->size(), 5u);
  EXPECT_EQ(suite->front().name, "campus_quad");
  EXPECT_EQ(suite->back().name, "warehouse_aisles");
}

TEST(SimWorldYamlTest, HandDrawnBlindStartWorldsLoad) {
  // Starts that face a wall or a dead end closely: the first frame shows little.
  const auto suite = LoadSuite(SEMNAV_SOURCE_DIR "/tests/worlds/hand_drawn_blind_starts");
  ASSERT_TRUE(suite.ok()) << suite.status();
  ASSERT_EQ(suite->size(), 1u);
  EXPECT_EQ(suite->front().name, "hotel_floor");
}

TEST(SimWorldYamlTest, RejectsLabelsTheLexiconDoesNotKnow) {
  ExpectInvalidField(Replace(kWorld, "label: refrigerator", "label: flux capacitor"),
                     "objects[0].label");
  ExpectInvalidField(Replace(kWorld, "label: refrigerator", "label: spaceship"),
                     "objects[0].label");
  // Any English form of a lexicon object is a label the gateway can name.
  EXPECT_TRUE(ParseWorldYaml(Replace(kWorld, "label: refrigerator", "label: sofa")).ok());
  EXPECT_TRUE(ParseWorldYaml(Replace(kWorld, "label: refrigerator", "label: table")).ok());
  EXPECT_TRUE(ParseWorldYaml(Replace(kWorld, "label: refrigerator", "label: trash can")).ok());
}

TEST(SimWorldYamlTest, RejectsGeometryOutsideTheBounds) {
  // The fridge reaches x = 6.35 in a world that ends at x = 6.
  ExpectInvalidField(Replace(kWorld, "center: [5, 3]", "center: [6, 3]"), "objects[0].box");
  ExpectInvalidField(
      Replace(kWorld, "center: [3, 0], size: [6, 0.1", "center: [3, 0], size: [6.4, 0.1"),
      "obstacles[0].box");
  ExpectInvalidField(Replace(kWorld, "[[1, 2], [2, 2], [2, 3]]", "[[1, 2], [2, 2], [2, 4.5]]"),
                     "obstacles[1].prism.polygon");
  ExpectInvalidField(Replace(kWorld, "[6, 4], [0, 4]]", "[6, 5], [0, 4]]"), "rooms[0].polygon");
  ExpectInvalidField(Replace(kWorld, "position: [1, 1, 0]", "position: [7, 1, 0]"),
                     "starts[0].position");
}

TEST(SimWorldYamlTest, RejectsStartsTouchingASolid) {
  // The ground robot's body has a 0.25 m radius: 0.2 m from the wall's face at y = 0.05 it
  // touches it, 0.3 m away it does not.
  ExpectInvalidField(Replace(kWorld, "position: [1, 1, 0]", "position: [1, 0.25, 0]"),
                     "starts[0].position");
  EXPECT_TRUE(
      ParseWorldYaml(Replace(kWorld, "position: [1, 1, 0]", "position: [1, 0.35, 0]")).ok());
  // Inside the fridge's footprint.
  ExpectInvalidField(Replace(kWorld, "position: [1, 1, 0]", "position: [5, 3, 0]"),
                     "starts[0].position");
  // A UAV at 1.5 m flies over the 0.9 m furniture that a ground robot would stand in.
  const std::string over_furniture =
      Replace(kWorld, "position: [1, 1, 0]", "position: [1.8, 2.2, 0]");
  ExpectInvalidField(over_furniture, "starts[0].position");
  EXPECT_TRUE(ParseWorldYaml(Replace(over_furniture, "[1.8, 2.2, 0], yaw: 0.5, modality: ground",
                                     "[1.8, 2.2, 1.5], yaw: 0.5, modality: uav"))
                  .ok());
}

TEST(SimWorldYamlTest, WriterRoundTrips) {
  absl::StatusOr<World> world = ParseWorldYaml(kWorld);
  ASSERT_TRUE(world.ok());
  world->starts[0].position.x() = 2.9504;  // written to the millimetre
  const std::string text = WorldToYaml(*world);
  EXPECT_NE(text.find("[2.95, "), std::string::npos) << text;
  const absl::StatusOr<World> again = ParseWorldYaml(text);
  ASSERT_TRUE(again.ok()) << again.status() << "\n" << text;
  EXPECT_EQ(WorldToYaml(*again), text);
  EXPECT_EQ(again->objects[0].colour, (Rgb{240, 240, 240}));
  EXPECT_EQ(std::get<PrismShape>(again->obstacles[1].shape).polygon.size(), 3u);
}

TEST(SimWorldYamlTest, SuiteIsEveryYamlFileSorted) {
  const std::string dir = ::testing::TempDir() + "/suite_test";
  std::filesystem::create_directories(dir);
  World world = *ParseWorldYaml(kWorld);
  world.name = "b";
  ASSERT_TRUE(SaveWorldFile(world, dir + "/b.yaml").ok());
  world.name = "a";
  ASSERT_TRUE(SaveWorldFile(world, dir + "/a.yaml").ok());
  const auto suite = LoadSuite(dir);
  ASSERT_TRUE(suite.ok()) << suite.status();
  ASSERT_EQ(suite->size(), 2u);
  EXPECT_EQ((*suite)[0].name, "a");
  EXPECT_EQ(LoadSuite(dir + "/missing").status().code(), absl::StatusCode::kNotFound);
}

}  // namespace
}  // namespace semnav::sim
