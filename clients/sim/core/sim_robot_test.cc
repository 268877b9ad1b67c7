#include "clients/sim/core/sim_robot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "clients/sim/core/test_worlds.h"

namespace semnav::sim {
namespace {

using testing::Box;

class SimRobotTest : public ::testing::Test {
 protected:
  SimRobotTest() : world_(testing::OpenWorld()) {
    // Wall across the +x direction, near face at x = 3.
    world_.obstacles.push_back(Obstacle{"wall", Rgb{}, Box(3.1, 0.0, 0.2, 4.0, 2.5)});
    // A low box (0.8 m) a fly-roll robot can fly over, at y = 3.
    world_.obstacles.push_back(Obstacle{"furniture", Rgb{}, Box(0.0, 3.0, 0.6, 0.6, 0.8)});
    world_.objects.push_back(testing::Object("chair_1", "chair", Box(-3.0, 0.0, 0.5, 0.5, 0.9)));
    scene_ = Scene::Build(world_);
  }

  SimRobot MakeRobot(Modality modality, uint64_t seed = 1, SensorConfig sensors = {}) {
    StartPose start;
    start.modality = modality;
    return SimRobot(world_, scene_, start, RobotConfig::ForModality(modality), sensors, seed);
  }

  static Waypoint At(double x, double y, double z = 0.0, MotionMode mode = MotionMode::kRoll) {
    return Waypoint{Eigen::Vector3d(x, y, z), mode};
  }

  World world_;
  Scene scene_;
};

TEST_F(SimRobotTest, FollowsPathAtRollSpeed) {
  SimRobot robot = MakeRobot(Modality::kGround);  // every bend turned in place
  ASSERT_TRUE(robot.Apply(FollowPath{{At(1.0, 0.0), At(1.0, -1.0)}}).ok());
  StepReport report = robot.Step(1.0);  // 0.5 m/s: half-way to the first waypoint
  EXPECT_EQ(report.activity, RobotActivity::kMoving);
  EXPECT_NEAR(robot.pose().position.x(), 0.5, 1e-9);
  robot.Step(1.0);
  EXPECT_NEAR(robot.pose().position.x(), 1.0, 1e-9);
  // Turning -90 degrees in place at 1 rad/s takes pi/2 s before moving on.
  robot.Step(std::numbers::pi / 2);
  EXPECT_NEAR(robot.pose().yaw, -std::numbers::pi / 2, 1e-6);
  EXPECT_NEAR(robot.pose().position.y(), 0.0, 1e-6);
  report = robot.Step(2.0);
  EXPECT_TRUE(report.arrived);
  EXPECT_NEAR(robot.pose().position.y(), -1.0, 1e-9);
  EXPECT_NEAR(robot.path_length_m(), 2.0, 1e-9);
  EXPECT_NEAR(robot.energy_j(), 800.0, 1e-6);  // 2 m rolling at 400 J/m
  EXPECT_NEAR(robot.time_s(), 4.0 + std::numbers::pi / 2, 1e-9);
}

TEST_F(SimRobotTest, TurnsOnTheMoveOnceTheRestOfTheTurnIsSmall) {
  RobotConfig config = RobotConfig::ForModality(Modality::kGround);  // 0.5 m/s, 1 rad/s
  config.turn_while_moving_max_rad = 0.785;
  SimRobot robot(world_, scene_, StartPose{}, config, SensorConfig{}, 1);
  ASSERT_TRUE(robot.Apply(FollowPath{{At(1.0, 0.0), At(1.0, -1.0)}}).ok());
  robot.Step(2.0);
  ASSERT_NEAR(robot.pose().position.x(), 1.0, 1e-9);
  // -pi/2 to turn: pi/2 - 0.785 rad in place, then moving while the last 0.785 rad turn.
  StepReport report = robot.Step(std::numbers::pi / 2 - 0.785);
  EXPECT_EQ(report.activity, RobotActivity::kTurning);
  EXPECT_NEAR(robot.pose().yaw, -(std::numbers::pi / 2 - 0.785), 1e-6);
  EXPECT_NEAR(robot.pose().position.y(), 0.0, 1e-9);
  report = robot.Step(0.5);
  EXPECT_EQ(report.activity, RobotActivity::kMoving);
  EXPECT_NEAR(robot.pose().position.y(), -0.25, 1e-6);  // on the segment, at full speed
  EXPECT_NEAR(robot.pose().yaw, -(std::numbers::pi / 2 - 0.785) - 0.5, 1e-6);
  report = robot.Step(1.5);
  EXPECT_TRUE(report.arrived);
  EXPECT_NEAR(robot.pose().yaw, -std::numbers::pi / 2, 1e-6);  // aligned on the way
  EXPECT_NEAR(robot.path_length_m(), 2.0, 1e-9);
  EXPECT_NEAR(robot.time_s(), 4.0 + std::numbers::pi / 2 - 0.785, 1e-9);

  // A 30-degree bend is taken without stopping: 2 m in 4 s.
  SimRobot bend(world_, scene_, StartPose{}, config, SensorConfig{}, 1);
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  ASSERT_TRUE(bend.Apply(FollowPath{{At(1.0, 0.0), At(1.0 + c, s)}}).ok());
  report = bend.Step(4.0);
  EXPECT_TRUE(report.arrived);
  EXPECT_NEAR(bend.pose().yaw, std::numbers::pi / 6, 1e-6);
}

TEST_F(SimRobotTest, CollisionIsReportedAndNotPassedThrough) {
  SimRobot robot = MakeRobot(Modality::kGround);
  ASSERT_TRUE(robot.Apply(FollowPath{{At(5.0, 0.0)}}).ok());
  StepReport report;
  for (int i = 0; i < 40 && !report.collision; ++i) report = robot.Step(0.5);
  ASSERT_TRUE(report.collision.has_value());
  EXPECT_EQ(report.collision->kind, "wall");
  // Radius 0.25 against the face at x = 3: halted within one 5 cm check of touching.
  EXPECT_LE(robot.pose().position.x(), 2.75 + 1e-9);
  EXPECT_GT(robot.pose().position.x(), 2.69);
  EXPECT_EQ(robot.collisions().size(), 1u);
  const double halted = robot.pose().position.x();
  robot.Step(5.0);  // no path left: stays put
  EXPECT_EQ(robot.pose().position.x(), halted);
}

TEST_F(SimRobotTest, ReverseWaypointBacksUpKeepingTheHeading) {
  SimRobot robot = MakeRobot(Modality::kGround);
  Waypoint back = At(-1.0, 0.0);
  back.reverse = true;
  ASSERT_TRUE(robot.Apply(FollowPath{{back}}).ok());
  const StepReport report = robot.Step(2.0);  // 1 m at 0.5 m/s, no turn first
  EXPECT_TRUE(report.arrived);
  EXPECT_NEAR(robot.pose().position.x(), -1.0, 1e-9);
  EXPECT_NEAR(robot.pose().yaw, 0.0, 1e-12);
  EXPECT_NEAR(robot.path_length_m(), 1.0, 1e-9);
}

TEST_F(SimRobotTest, ObjectsAreSolidToo) {
  SimRobot robot = MakeRobot(Modality::kGround);
  ASSERT_TRUE(robot.Apply(FollowPath{{At(-5.0, 0.0)}}).ok());
  StepReport report;
  for (int i = 0; i < 40 && !report.collision; ++i) report = robot.Step(0.5);
  ASSERT_TRUE(report.collision.has_value());
  EXPECT_EQ(report.collision->object_index, 0);
}

TEST_F(SimRobotTest, FlyRollFliesOverLowObstacleAndPaysFlightEnergy) {
  SimRobot robot = MakeRobot(Modality::kFlyRoll);
  // Take off to 1 m, cross the 0.8 m box, land, at 1 m/s flying.
  ASSERT_TRUE(robot
                  .Apply(FollowPath{{At(0, 2.0), At(0, 2.0, 1.0, MotionMode::kFly),
                                     At(0, 4.0, 1.0, MotionMode::kFly), At(0, 4.0)}})
                  .ok());
  StepReport report;
  for (int i = 0; i < 200 && !report.arrived; ++i) {
    report = robot.Step(0.1);
    ASSERT_FALSE(report.collision.has_value()) << robot.pose().position.transpose();
  }
  ASSERT_TRUE(report.arrived);
  EXPECT_NEAR(robot.roll_distance_m(), 2.0, 1e-9);  // 2 m out
  EXPECT_NEAR(robot.fly_distance_m(), 4.0, 1e-9);   // 1 m up, 2 m across, 1 m down
  EXPECT_NEAR(robot.energy_j(), 2 * 400.0 + 4 * 800.0, 1e-6);
  // Turn pi/2 at 1 rad/s, 2 m at 0.5 m/s, 4 m at 1 m/s.
  EXPECT_NEAR(robot.time_s(), 8.0 + std::numbers::pi / 2, 0.1 + 1e-9);
  // The same crossing rolling would hit the box.
  SimRobot roller = MakeRobot(Modality::kFlyRoll);
  ASSERT_TRUE(roller.Apply(FollowPath{{At(0, 4.0)}}).ok());
  report = {};
  for (int i = 0; i < 100 && !report.collision; ++i) report = roller.Step(0.1);
  EXPECT_TRUE(report.collision.has_value());
}

TEST_F(SimRobotTest, InvalidCommandsLeaveStateUnchanged) {
  SimRobot robot = MakeRobot(Modality::kGround);
  EXPECT_EQ(robot.Apply(FollowPath{}).code(), absl::StatusCode::kInvalidArgument);
  const absl::Status fly = robot.Apply(FollowPath{{At(1, 0), At(2, 0, 1.0, MotionMode::kFly)}});
  EXPECT_EQ(fly.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(std::string(fly.message()).find("waypoints[1].mode"), std::string::npos);
  robot.Step(1.0);
  EXPECT_EQ(robot.pose().position, Eigen::Vector3d::Zero());
  ASSERT_TRUE(robot.Apply(Stop{}).ok());
  EXPECT_TRUE(robot.stopped());
  EXPECT_EQ(robot.Apply(Hold{}).code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(robot.Step(1.0).activity, RobotActivity::kStopped);
}

TEST_F(SimRobotTest, RotateTurnsAtTheYawRate) {
  SimRobot robot = MakeRobot(Modality::kUav);  // 2 rad/s
  ASSERT_TRUE(robot.Apply(Rotate{std::numbers::pi / 2}).ok());
  robot.Step(0.5);
  EXPECT_NEAR(robot.pose().yaw, 1.0, 1e-9);
  robot.Step(0.5);
  EXPECT_NEAR(robot.pose().yaw, std::numbers::pi / 2, 1e-9);
}

TEST_F(SimRobotTest, SameSeedSameFrames) {
  SensorConfig sensors;
  sensors.intrinsics.width = 160;
  sensors.intrinsics.height = 120;
  sensors.intrinsics.fx = sensors.intrinsics.fy = 131.25;
  sensors.intrinsics.cx = 79.5;
  sensors.intrinsics.cy = 59.5;
  sensors.odometry.enabled = true;
  sensors.detector.false_positive_rate = 2.0;
  auto run = [&](uint64_t seed) {
    SimRobot robot = MakeRobot(Modality::kGround, seed, sensors);
    EXPECT_TRUE(robot.Apply(FollowPath{{At(2.0, 0.0), At(2.0, 2.0)}}).ok());
    std::vector<SensorFrame> frames;
    for (int i = 0; i < 5; ++i) {
      robot.Step(0.7);
      frames.push_back(robot.Capture());
    }
    return frames;
  };
  const auto a = run(9), b = run(9), c = run(10);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].depth, b[i].depth);
    EXPECT_EQ(a[i].odometry_pose.position, b[i].odometry_pose.position);
    EXPECT_EQ(a[i].detections.detections.size(), b[i].detections.detections.size());
    EXPECT_EQ(a[i].true_pose.position, c[i].true_pose.position);  // motion is noise free
  }
  EXPECT_NE(a.back().depth, c.back().depth);
  // With drift on, odometry departs from the truth.
  EXPECT_GT((a.back().odometry_pose.position - a.back().true_pose.position).norm(), 1e-6);
}

}  // namespace
}  // namespace semnav::sim
