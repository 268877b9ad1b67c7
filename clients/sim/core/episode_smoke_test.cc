// A scripted episode through the whole core: see the target, drive to it, stop, score.
#include <gtest/gtest.h>

#include "clients/sim/core/episode_metrics.h"
#include "clients/sim/core/sim_robot.h"
#include "clients/sim/core/test_worlds.h"

namespace semnav::sim {
namespace {

TEST(SimEpisodeSmokeTest, SeeDriveStopAndScore) {
  World world = testing::OpenWorld();
  // A chair whose near face is at x = 3.75, straight ahead of the start.
  world.objects.push_back(
      testing::Object("chair_1", "chair", testing::Box(4.0, 0.0, 0.5, 0.5, 0.9)));
  const Scene scene = Scene::Build(world);
  SensorConfig sensors;
  sensors.detector.miss_rate = 0.0;
  SimRobot robot(world, scene, world.starts[0], RobotConfig::ForModality(Modality::kGround),
                 sensors, 3);
  const SensorFrame first = robot.Capture();
  bool saw_chair = false;
  for (const Detection& d : first.detections.detections) saw_chair |= d.object_index == 0;
  EXPECT_TRUE(saw_chair);
  ASSERT_TRUE(robot.Apply(FollowPath{{Waypoint{Eigen::Vector3d(3.3, 0, 0)}}}).ok());
  StepReport report;
  for (int i = 0; i < 100 && !report.arrived; ++i) report = robot.Step(0.25);
  ASSERT_TRUE(report.arrived);
  ASSERT_TRUE(robot.Apply(Stop{}).ok());
  const GroundTruthGrid grid =
      RasterizeOccupancy(world, BodyRaster(RobotConfig::ForModality(Modality::kGround), 0.0));
  const StopOutcome stop = ScoreStop(world, SuccessRegion::Build(world, "chair", grid), "chair",
                                     robot.pose().position.head<2>(), robot.stopped());
  EXPECT_TRUE(stop.success);
  EXPECT_NEAR(stop.distance_to_goal_m, 0.45, 1e-9);
  // Shortest path: to 1 m from the face, 3.75 - 1 = 2.75 m; taken 3.3 m.
  EXPECT_NEAR(SuccessWeightedPathLength(stop.success, 2.75, robot.path_length_m()), 2.75 / 3.3,
              1e-9);
  EXPECT_NEAR(robot.time_s(), 3.3 / 0.5, 0.25);
  EXPECT_NEAR(robot.energy_j(), 3.3 * 400.0, 1e-6);
}

}  // namespace
}  // namespace semnav::sim
