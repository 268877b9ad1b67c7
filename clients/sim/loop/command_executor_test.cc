#include "clients/sim/loop/command_executor.h"

#include <gtest/gtest.h>

#include "clients/sim/core/scene.h"
#include "clients/sim/core/test_worlds.h"

namespace semnav::sim::loop {
namespace {

namespace api = semnav::reasoning::v1;

class CommandExecutorTest : public ::testing::Test {
 protected:
  CommandExecutorTest()
      : world_(MakeWorld()),
        scene_(Scene::Build(world_)),
        robot_(world_, scene_, world_.starts[0], RobotConfig::ForModality(Modality::kGround),
               SensorConfig{}, 1),
        executor_(robot_) {}

  // The open 10 x 10 m square with a wall across x = 3.
  static World MakeWorld() {
    World world = testing::OpenWorld();
    world.obstacles.push_back(Obstacle{"wall", Rgb{}, testing::Box(3.0, 0.0, 0.1, 10.0, 2.0)});
    return world;
  }

  std::optional<Feedback> RunUntilOutcome(int max_steps) {
    for (int i = 0; i < max_steps; ++i) {
      if (std::optional<Feedback> f = executor_.Step(0.5); f.has_value()) return f;
    }
    return std::nullopt;
  }

  World world_;
  Scene scene_;
  SimRobot robot_;
  CommandExecutor executor_;
};

api::RobotCommand Navigate(uint64_t id, double x, double y, double yaw, bool with_path) {
  api::RobotCommand command;
  command.set_command_id(id);
  api::NavigateAction* nav = command.mutable_navigate();
  nav->mutable_goal()->set_x(x);
  nav->mutable_goal()->set_y(y);
  nav->set_goal_yaw(yaw);
  if (with_path) {
    api::PathWaypoint* w = nav->add_path();
    w->mutable_position()->set_x(x);
    w->mutable_position()->set_y(y);
  }
  return command;
}

TEST_F(CommandExecutorTest, NavigateArrivesThenFacesGoalYaw) {
  const Feedback accepted = executor_.Start(Navigate(7, 0.0, 2.0, 0.0, true));
  EXPECT_EQ(accepted.kind, api::FEEDBACK_KIND_ACCEPTED);
  EXPECT_EQ(accepted.command_id, 7u);
  const std::optional<Feedback> outcome = RunUntilOutcome(40);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->kind, api::FEEDBACK_KIND_GOAL_REACHED);
  EXPECT_EQ(outcome->command_id, 7u);
  EXPECT_NEAR(robot_.pose().position.y(), 2.0, 1e-6);
  EXPECT_NEAR(robot_.pose().yaw, 0.0, 0.05);
}

TEST_F(CommandExecutorTest, EmptyPathDrivesStraightBacksUpTwiceThenReportsBlockedAtTheWall) {
  ASSERT_EQ(executor_.Start(Navigate(1, 4.5, 0.0, 0.0, false)).kind, api::FEEDBACK_KIND_ACCEPTED);
  const std::optional<Feedback> outcome = RunUntilOutcome(40);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->kind, api::FEEDBACK_KIND_BLOCKED);
  // Two recoveries (back up 0.25 m facing the wall, try again), then the third contact is reported.
  EXPECT_EQ(robot_.collisions().size(), 3u);
  EXPECT_NEAR(robot_.pose().yaw, 0.0, 1e-9);  // backed up without turning round
  // Halted before the wall face at x = 2.95 minus the 0.25 m radius.
  EXPECT_LT(robot_.pose().position.x(), 2.71);
  EXPECT_GT(robot_.pose().position.x(), 2.5);
}

TEST_F(CommandExecutorTest, RotateTurnsAtTheRateForTheDuration) {
  api::RobotCommand command;
  command.set_command_id(3);
  command.mutable_rotate()->set_angular_speed_rps(0.5);
  command.mutable_rotate()->set_duration_s(2.0);
  ASSERT_EQ(executor_.Start(command).kind, api::FEEDBACK_KIND_ACCEPTED);
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(executor_.Step(0.5).has_value());
  const std::optional<Feedback> outcome = executor_.Step(0.5);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->kind, api::FEEDBACK_KIND_GOAL_REACHED);
  EXPECT_NEAR(robot_.pose().yaw, 1.0, 1e-6);
}

// The camera looks 0.5 rad higher while the rotation runs (a wall clock's turn), and back at its
// default pitch once it ends; a tilt beyond the head's 0.6 rad fails and changes nothing.
TEST_F(CommandExecutorTest, ARotationWithTheCameraTiltedUpCapturesHigherAndEndsLevel) {
  const double default_pitch = RobotConfig::ForModality(Modality::kGround).camera_pitch;
  auto camera_pitch = [&] {  // from the captured frame: the camera's +z (optical axis) in the world
    const SensorFrame frame = robot_.Capture();
    const Eigen::Vector3d axis = frame.world_from_camera.linear() * Eigen::Vector3d::UnitZ();
    return -std::asin(axis.z());  // positive looks down
  };
  EXPECT_NEAR(camera_pitch(), default_pitch, 1e-9);
  api::RobotCommand command;
  command.set_command_id(4);
  command.mutable_rotate()->set_angular_speed_rps(0.5);
  command.mutable_rotate()->set_duration_s(1.0);
  command.mutable_rotate()->set_camera_tilt_rad(0.5);
  ASSERT_EQ(executor_.Start(command).kind, api::FEEDBACK_KIND_ACCEPTED);
  EXPECT_FALSE(executor_.Step(0.5).has_value());
  EXPECT_NEAR(camera_pitch(), default_pitch - 0.5, 1e-9);
  ASSERT_TRUE(executor_.Step(0.5).has_value());
  EXPECT_NEAR(camera_pitch(), default_pitch, 1e-9);

  command.set_command_id(5);
  command.mutable_rotate()->set_camera_tilt_rad(0.7);
  const Feedback refused = executor_.Start(command);
  EXPECT_EQ(refused.kind, api::FEEDBACK_KIND_FAILED);
  EXPECT_NE(refused.detail.find("camera_tilt_rad"), std::string::npos);
  EXPECT_NEAR(camera_pitch(), default_pitch, 1e-9);
}

TEST_F(CommandExecutorTest, HoldEndsAfterItsDuration) {
  api::RobotCommand command;
  command.set_command_id(4);
  command.mutable_hold()->set_duration_s(1.0);
  ASSERT_EQ(executor_.Start(command).kind, api::FEEDBACK_KIND_ACCEPTED);
  EXPECT_FALSE(executor_.Step(0.5).has_value());
  ASSERT_TRUE(executor_.Step(0.5).has_value());
  EXPECT_DOUBLE_EQ(robot_.time_s(), 1.0);
  EXPECT_EQ(robot_.path_length_m(), 0.0);
}

TEST_F(CommandExecutorTest, TaskStopIsTheStopActionButEmergencyStopIsNot) {
  api::RobotCommand command;
  command.set_command_id(5);
  command.mutable_stop()->set_emergency(true);
  executor_.Start(command);
  EXPECT_FALSE(executor_.stop_issued());
  command.mutable_stop()->set_emergency(false);
  executor_.Start(command);
  EXPECT_TRUE(executor_.stop_issued());
  // After the final stop the robot refuses to move.
  EXPECT_EQ(executor_.Start(Navigate(6, 1.0, 0.0, 0.0, true)).kind, api::FEEDBACK_KIND_FAILED);
}

TEST_F(CommandExecutorTest, FlightWaypointFailsOnAGroundRobot) {
  api::RobotCommand command = Navigate(8, 1.0, 0.0, 0.0, true);
  command.mutable_navigate()->mutable_path(0)->mutable_position()->set_z(1.5);
  command.mutable_navigate()->mutable_path(0)->set_mode(api::LOCOMOTION_MODE_AIR);
  const Feedback feedback = executor_.Start(command);
  EXPECT_EQ(feedback.kind, api::FEEDBACK_KIND_FAILED);
  EXPECT_FALSE(feedback.detail.empty());
}

// A fly-roll robot (radius 0.2 m, body 0.05-0.4 m) in the square with a 1 m crate across x = 3.
class FlyRollExecutorTest : public ::testing::Test {
 protected:
  FlyRollExecutorTest()
      : world_(MakeWorld()),
        scene_(Scene::Build(world_)),
        robot_(world_, scene_, world_.starts[0], RobotConfig::ForModality(Modality::kFlyRoll),
               SensorConfig{}, 1),
        executor_(robot_) {}

  static World MakeWorld() {
    World world = testing::OpenWorld();
    world.starts[0].modality = Modality::kFlyRoll;
    world.obstacles.push_back(Obstacle{"crate", Rgb{}, testing::Box(3.0, 0.0, 0.4, 10.0, 1.0)});
    return world;
  }

  std::optional<Feedback> RunUntilOutcome(int max_steps) {
    for (int i = 0; i < max_steps; ++i) {
      if (std::optional<Feedback> f = executor_.Step(0.5); f.has_value()) return f;
    }
    return std::nullopt;
  }

  static void Add(api::NavigateAction* nav, double x, double z, api::LocomotionMode mode) {
    api::PathWaypoint* w = nav->add_path();
    w->mutable_position()->set_x(x);
    w->mutable_position()->set_z(z);
    w->set_mode(mode);
  }

  World world_;
  Scene scene_;
  SimRobot robot_;
  CommandExecutor executor_;
};

// The gateway's multi-modal path (planning_client RobotPath): roll, climb, fly over, land, roll.
TEST_F(FlyRollExecutorTest, ClimbsFliesOverTheCrateAndLands) {
  api::RobotCommand command;
  command.set_command_id(1);
  api::NavigateAction* nav = command.mutable_navigate();
  nav->mutable_goal()->set_x(4.5);
  Add(nav, 2.4, 0.0, api::LOCOMOTION_MODE_GROUND);
  Add(nav, 2.4, 1.3, api::LOCOMOTION_MODE_AIR);
  Add(nav, 3.6, 1.3, api::LOCOMOTION_MODE_AIR);
  Add(nav, 3.6, 0.0, api::LOCOMOTION_MODE_AIR);
  Add(nav, 4.5, 0.0, api::LOCOMOTION_MODE_GROUND);
  ASSERT_EQ(executor_.Start(command).kind, api::FEEDBACK_KIND_ACCEPTED);
  const std::optional<Feedback> outcome = RunUntilOutcome(60);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->kind, api::FEEDBACK_KIND_GOAL_REACHED) << outcome->detail;
  EXPECT_TRUE(robot_.collisions().empty());
  EXPECT_NEAR(robot_.pose().position.x(), 4.5, 1e-6);
  EXPECT_NEAR(robot_.pose().position.z(), 0.0, 1e-9);
  EXPECT_NEAR(robot_.fly_distance_m(), 1.3 + 1.2 + 1.3, 1e-6);
}

// Regression (flyroll_01/02: "robot blocked" loops): after a contact the fly-roll robot drove
// straight for the goal twice more (its recovery is a ground robot's local re-plan, which it does
// not have), touching the same crate each time. Now it backs up once and reports BLOCKED, so the
// gateway re-plans with more clearance.
TEST_F(FlyRollExecutorTest, AContactBacksUpOnceThenReportsBlocked) {
  api::RobotCommand command;
  command.set_command_id(2);
  command.mutable_navigate()->mutable_goal()->set_x(4.5);
  Add(command.mutable_navigate(), 4.5, 0.0, api::LOCOMOTION_MODE_GROUND);
  ASSERT_EQ(executor_.Start(command).kind, api::FEEDBACK_KIND_ACCEPTED);
  const std::optional<Feedback> outcome = RunUntilOutcome(40);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_EQ(outcome->kind, api::FEEDBACK_KIND_BLOCKED);
  EXPECT_EQ(outcome->detail, "collision with crate");
  EXPECT_EQ(robot_.collisions().size(), 1u);
  // Halted before the crate face at x = 2.8 less the 0.2 m radius, then 0.25 m back.
  EXPECT_LT(robot_.pose().position.x(), 2.6 - 0.25 + 1e-6);
  EXPECT_GT(robot_.pose().position.x(), 2.25);
  EXPECT_NEAR(robot_.pose().yaw, 0.0, 1e-9);
}

}  // namespace
}  // namespace semnav::sim::loop
