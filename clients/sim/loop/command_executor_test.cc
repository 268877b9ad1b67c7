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

}  // namespace
}  // namespace semnav::sim::loop
