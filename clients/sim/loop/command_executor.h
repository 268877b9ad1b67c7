// Executes the gateway's robot-session commands with a SimRobot, one simulated step at a time,
// and says which feedback the robot owes the gateway.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "clients/sim/core/sim_robot.h"
#include "clients/sim/loop/local_planner.h"
#include "semnav/reasoning/v1/robot_session.pb.h"

namespace semnav::sim::loop {

struct Feedback {
  uint64_t command_id = 0;
  semnav::reasoning::v1::FeedbackKind kind = semnav::reasoning::v1::FEEDBACK_KIND_UNSPECIFIED;
  std::string detail;
};

class CommandExecutor {
 public:
  // Without a local planner, navigate commands without a path head straight for the goal.
  explicit CommandExecutor(SimRobot& robot, LocalPlanFn local_planner = {})
      : robot_(robot), local_planner_(std::move(local_planner)) {}

  // Starts a command (superseding the current one). Returns ACCEPTED, or FAILED with the
  // robot's error (e.g. a fly waypoint for a ground robot).
  Feedback Start(const semnav::reasoning::v1::RobotCommand& command);
  // Advances the robot by dt seconds; returns the command's outcome when it ends this step:
  // GOAL_REACHED (navigate arrived and faced goal_yaw, rotation/hold duration elapsed),
  // BLOCKED (collision that backing up and re-planning could not get past).
  std::optional<Feedback> Step(double dt);
  // The robot was carried away (SimRobot::Kidnap): the command in progress ends without feedback.
  void Interrupt() {
    phase_ = Phase::kIdle;
    local_goal_.reset();
    robot_.SetCameraTilt(0.0).IgnoreError();
  }
  // True once a (non-emergency) STOP was executed: the episode's stop action.
  bool stop_issued() const { return robot_.stopped(); }

 private:
  // kBackingUp: a fly-roll robot backs away from what it touched, then reports BLOCKED.
  enum class Phase { kIdle, kDriving, kFacing, kRotating, kHolding, kBackingUp };
  Feedback Done(semnav::reasoning::v1::FeedbackKind kind, std::string detail);
  absl::StatusOr<FollowPath> ToFollowPath(const semnav::reasoning::v1::NavigateAction& navigate);
  absl::StatusOr<FollowPath> PlanLocally(const Eigen::Vector3d& from,
                                         const Eigen::Vector3d& goal) const;
  // After a collision: back up and re-plan to the navigate goal; false when the recoveries are used
  // up.
  bool Recover();
  // kBackUpM behind the robot along its heading.
  Eigen::Vector3d BackUpPoint() const;
  // A fly-roll robot after a collision: it has no local planner for flight, and heading straight
  // for the goal hits the same obstacle again, so it backs up (at its altitude) and hands the
  // re-plan to the gateway (BLOCKED once backed up). False when it cannot back up.
  bool BackUpThenReport(std::string detail);

  SimRobot& robot_;
  LocalPlanFn local_planner_;
  Phase phase_ = Phase::kIdle;
  uint64_t command_id_ = 0;
  double goal_yaw_ = 0.0;
  double rate_rps_ = 0.0;
  double remaining_s_ = 0.0;                   // < 0: until the next command
  std::optional<Eigen::Vector3d> local_goal_;  // set while driving a locally planned path
  Eigen::Vector3d navigate_goal_ = Eigen::Vector3d::Zero();  // where the current navigate ends
  int recoveries_ = 0;          // back-up and re-plan attempts of this command
  std::string blocked_detail_;  // kBackingUp: what the robot touched
  double since_plan_s_ = 0.0;
};

}  // namespace semnav::sim::loop
