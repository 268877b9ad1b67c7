#include "clients/sim/loop/search_episode.h"

#include <gtest/gtest.h>

#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/shape_queries.h"
#include "clients/sim/core/test_worlds.h"
#include "clients/sim/loop/shortest_path.h"
#include "clients/sim/worlds/indoor_generator.h"

namespace semnav::sim::loop {
namespace {

std::string RoomTypeAt(const World& world, const Eigen::Vector2d& point) {
  for (const Room& room : world.rooms) {
    if (PointInPolygon(room.polygon, point)) return room.type;
  }
  return "";
}

RobotConfig DemoCamera() {
  RobotConfig robot = RobotConfig::ForModality(Modality::kGround);
  robot.camera_pitch = EpisodeSpec{}.ground_camera_pitch;
  return robot;
}

// A 10 x 10 m square; the robot at the origin faces +x. A wall along x = 2 runs from the south
// edge to y = 2.5, leaving a 2.5 m gap in the north. A chair 2 m behind the robot, a bed behind
// the wall at (3.5, -2).
World WallWorld() {
  World world = testing::OpenWorld();
  world.obstacles.push_back(Obstacle{"wall", Rgb{}, testing::Box(2.0, -1.25, 0.1, 7.5, 2.6)});
  world.objects.push_back(
      testing::Object("chair_1", "chair", testing::Box(-2.0, 0.0, 0.5, 0.5, 0.9)));
  world.objects.push_back(testing::Object("bed_1", "bed", testing::Box(3.5, -2.0, 1.0, 1.0, 0.5)));
  return world;
}

TEST(SimLoopSearchEpisodeTest, ATurnOnTheSpotSeesBehindTheRobotButNotBehindAWall) {
  const World world = WallWorld();
  const Scene scene = Scene::Build(world);
  EXPECT_EQ(ObjectsInSightFrom(world, scene, world.starts[0], DemoCamera(), LoopSensorConfig()),
            std::set<int>{0});
  // Without the wall the bed, 3 m ahead and 2 m to the right, is in sight as well.
  World open = world;
  open.obstacles.clear();
  EXPECT_EQ(ObjectsInSightFrom(open, Scene::Build(open), open.starts[0], DemoCamera(),
                               LoopSensorConfig()),
            (std::set<int>{0, 1}));
}

TEST(SimLoopSearchEpisodeTest, TheTargetIsTheHiddenLabelAroundTheWall) {
  const World world = WallWorld();
  const GroundTruthGrid grid = RasterizeOccupancy(world, BodyRaster(DemoCamera(), 0.0));
  const std::vector<SearchTarget> targets = OutOfSightTargets(
      world, grid, Eigen::Vector2d::Zero(), {0}, kSearchMinPathM, kSearchMaxPathM);
  ASSERT_EQ(targets.size(), 1u);
  EXPECT_EQ(targets[0].label, "bed");
  // By hand: round the wall's end grown by the 0.25 m radius, (1.7, 2.75) to (2.3, 2.75), then
  // to 1 m from the bed's corner (3, -1.5): 3.23 + 0.6 + 3.31 = 7.14 m; the 8-connected grid
  // path runs a few percent longer (7.38 m).
  EXPECT_GT(targets[0].shortest_path_m, 7.1);
  EXPECT_LT(targets[0].shortest_path_m, 7.6);
  // Further than the search wants, or a bed in sight: no target.
  EXPECT_TRUE(OutOfSightTargets(world, grid, Eigen::Vector2d::Zero(), {0}, 8.0, 12.0).empty());
  EXPECT_TRUE(OutOfSightTargets(world, grid, Eigen::Vector2d::Zero(), {0, 1}, 4.0, 12.0).empty());
  // A bed whose footprint reaches within 1 m of the start starts inside the success region.
  World near = world;
  near.objects.push_back(testing::Object("bed_2", "bed", testing::Box(0.0, -1.3, 1.0, 0.6, 0.5)));
  EXPECT_TRUE(OutOfSightTargets(near, RasterizeOccupancy(near, BodyRaster(DemoCamera(), 0.0)),
                                Eigen::Vector2d::Zero(), {0}, kSearchMinPathM, kSearchMaxPathM)
                  .empty());
  // A cup on a table behind the wall is not a target either: only floor-standing furniture is.
  World cup = world;
  cup.objects.push_back(testing::Object("cup_1", "cup", testing::Box(3.5, -4.0, 0.1, 0.1, 0.1)));
  cup.objects.back().box.base_z = 0.75;
  const std::vector<SearchTarget> with_cup =
      OutOfSightTargets(cup, RasterizeOccupancy(cup, BodyRaster(DemoCamera(), 0.0)),
                        Eigen::Vector2d::Zero(), {0}, 4.0, 12.0);
  ASSERT_EQ(with_cup.size(), 1u);
  EXPECT_EQ(with_cup[0].label, "bed");
}

// The demo's episode, checked against the home's plan (demo_home_11, docs/simulation.md): the
// robot starts in the study at (5.2, 8.25) with a desk, chairs, a book and a laptop in view. The
// nearest out-of-sight target by path is the bed, 4.33 m away. The only couch stands in the
// living room to the south behind walls, 9.11 m away by path to its success region: the 7.66 m
// of the planar 1 m disc ended north of the living room's wall, 0.96 m from the couch through it.
TEST(SimLoopSearchEpisodeTest, TheDemoLooksForTheNearestTargetItCannotSee) {
  absl::StatusOr<EpisodeSpec> spec = SearchEpisode();
  ASSERT_TRUE(spec.ok()) << spec.status();
  EXPECT_EQ(spec->world.name, "demo_home_11");
  EXPECT_EQ(spec->start_index, 0);
  EXPECT_EQ(spec->target, "bed");
  EXPECT_EQ(spec->strategy, "SEMANTIC_FRONTIER");
  const StartPose& start = spec->world.starts[0];
  EXPECT_NEAR(start.position.x(), 5.2, 0.05);
  EXPECT_NEAR(start.position.y(), 8.25, 0.05);
  EXPECT_EQ(RoomTypeAt(spec->world, start.position.head<2>()), "study");

  std::set<std::string> in_sight;
  for (const int i : ObjectsInSightFrom(spec->world, Scene::Build(spec->world), start, DemoCamera(),
                                        spec->sensors)) {
    in_sight.insert(spec->world.objects[static_cast<size_t>(i)].label);
  }
  EXPECT_EQ(in_sight, (std::set<std::string>{"book", "chair", "desk", "laptop"}));
  // Independently of the renderer: the straight line from the camera to each couch's centre at
  // its top hits a wall first.
  const Eigen::Vector3d camera = start.position + Eigen::Vector3d(0, 0, DemoCamera().camera_height);
  int couches = 0;
  for (const ObjectInstance& object : spec->world.objects) {
    if (object.label != "couch") continue;
    ++couches;
    EXPECT_EQ(RoomTypeAt(spec->world, object.box.center), "living_room");
    const Eigen::Vector3d to =
        Eigen::Vector3d(object.box.center.x(), object.box.center.y(), object.box.top_z());
    const double length = (to - camera).norm();
    bool blocked = false;
    for (const Obstacle& obstacle : spec->world.obstacles) {
      blocked =
          blocked || (obstacle.kind == "wall" &&
                      IntersectRay(obstacle.shape, camera, (to - camera) / length, 0.0, length));
    }
    EXPECT_TRUE(blocked) << object.id;
  }
  EXPECT_EQ(couches, 1);

  RobotConfig robot = DemoCamera();
  const GroundTruthGrid grid =
      RasterizeOccupancy(spec->world, BodyRaster(robot, start.position.z()));
  const std::optional<NearestGoal> goal = NearestSuccessPoint(
      spec->world, grid, start.position.head<2>(), "couch", kDefaultSuccessRadius);
  ASSERT_TRUE(goal.has_value());  // reachable
  EXPECT_NEAR(goal->length_m, 9.11, 0.05);
  const std::optional<NearestGoal> bed = NearestSuccessPoint(
      spec->world, grid, start.position.head<2>(), "bed", kDefaultSuccessRadius);
  ASSERT_TRUE(bed.has_value());
  EXPECT_NEAR(bed->length_m, 4.33, 0.05);
}

}  // namespace
}  // namespace semnav::sim::loop
