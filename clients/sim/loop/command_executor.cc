#include "clients/sim/loop/command_executor.h"

#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"

namespace semnav::sim::loop {
namespace {

namespace api = semnav::reasoning::v1;

constexpr double kFacingTolerance = 0.05;  // rad, as RobotConfig::heading_tolerance
constexpr double kReplanPeriodS = 1.0;     // simulated seconds between local re-plans
// Nav2's recovery: after a collision back up this far and plan again, at most this often per
// navigate command, before reporting BLOCKED to the gateway.
constexpr double kBackUpM = 0.25;
constexpr int kMaxRecoveries = 2;

MotionMode ToMotionMode(api::LocomotionMode mode, Modality modality) {
  if (mode == api::LOCOMOTION_MODE_AIR) return MotionMode::kFly;
  if (mode == api::LOCOMOTION_MODE_UNSPECIFIED && modality == Modality::kUav)
    return MotionMode::kFly;
  return MotionMode::kRoll;
}

}  // namespace

absl::StatusOr<FollowPath> CommandExecutor::PlanLocally(const Eigen::Vector3d& from,
                                                        const Eigen::Vector3d& goal) const {
  absl::StatusOr<std::vector<Eigen::Vector2d>> path =
      local_planner_(from.head<2>(), goal.head<2>());
  if (!path.ok()) return path.status();
  FollowPath follow;
  const MotionMode mode = ToMotionMode(api::LOCOMOTION_MODE_UNSPECIFIED, robot_.modality());
  for (const Eigen::Vector2d& p : *path)
    follow.waypoints.push_back(Waypoint{Eigen::Vector3d(p.x(), p.y(), goal.z()), mode});
  return follow;
}

absl::StatusOr<FollowPath> CommandExecutor::ToFollowPath(const api::NavigateAction& navigate) {
  local_goal_.reset();
  const Modality modality = robot_.modality();
  FollowPath follow;
  for (const api::PathWaypoint& w : navigate.path()) {
    follow.waypoints.push_back(
        Waypoint{Eigen::Vector3d(w.position().x(), w.position().y(), w.position().z()),
                 ToMotionMode(w.mode(), modality)});
  }
  if (!follow.waypoints.empty()) return follow;
  // An empty path leaves planning to the robot.
  const Eigen::Vector3d goal(navigate.goal().x(), navigate.goal().y(), navigate.goal().z());
  const Eigen::Vector3d& here = robot_.pose().position;
  if ((goal - here).head<2>().norm() <= 1e-3) return follow;
  const MotionMode mode = ToMotionMode(api::LOCOMOTION_MODE_UNSPECIFIED, modality);
  if (!local_planner_) {  // straight for the goal; contact is reported as BLOCKED
    follow.waypoints.push_back(Waypoint{goal, mode});
    return follow;
  }
  local_goal_ = goal;
  since_plan_s_ = 0.0;
  return PlanLocally(here, goal);
}

Eigen::Vector3d CommandExecutor::BackUpPoint() const {
  const Pose& pose = robot_.pose();
  return pose.position - kBackUpM * Eigen::Vector3d(std::cos(pose.yaw), std::sin(pose.yaw), 0.0);
}

bool CommandExecutor::Recover() {
  if (recoveries_ >= kMaxRecoveries) return false;
  ++recoveries_;
  const Eigen::Vector3d back = BackUpPoint();
  FollowPath follow;
  follow.waypoints.push_back(
      Waypoint{back, ToMotionMode(api::LOCOMOTION_MODE_UNSPECIFIED, robot_.modality()), true});
  // Ground robots plan around what the map now shows; the others keep the gateway's path.
  if (local_planner_ && robot_.modality() == Modality::kGround) {
    absl::StatusOr<FollowPath> path = PlanLocally(back, navigate_goal_);
    if (path.ok())
      follow.waypoints.insert(follow.waypoints.end(), path->waypoints.begin(),
                              path->waypoints.end());
  }
  if (follow.waypoints.size() == 1) {
    follow.waypoints.push_back(Waypoint{
        navigate_goal_, ToMotionMode(api::LOCOMOTION_MODE_UNSPECIFIED, robot_.modality())});
  }
  since_plan_s_ = 0.0;
  return robot_.Apply(follow).ok();
}

bool CommandExecutor::BackUpThenReport(std::string detail) {
  const MotionMode mode = robot_.pose().position.z() > 1e-6 ? MotionMode::kFly : MotionMode::kRoll;
  FollowPath follow;
  follow.waypoints.push_back(Waypoint{BackUpPoint(), mode, true});
  if (!robot_.Apply(follow).ok()) return false;
  blocked_detail_ = std::move(detail);
  phase_ = Phase::kBackingUp;
  return true;
}

Feedback CommandExecutor::Done(api::FeedbackKind kind, std::string detail) {
  phase_ = Phase::kIdle;
  robot_.SetCameraTilt(0.0).IgnoreError();  // a tilt lasts for its command only
  return Feedback{command_id_, kind, std::move(detail)};
}

Feedback CommandExecutor::Start(const api::RobotCommand& command) {
  command_id_ = command.command_id();
  double tilt = 0.0;  // a tilt lasts for its command only
  if (command.action_case() == api::RobotCommand::kRotate)
    tilt = command.rotate().camera_tilt_rad();
  if (command.action_case() == api::RobotCommand::kHold) tilt = command.hold().camera_tilt_rad();
  if (absl::Status s = robot_.SetCameraTilt(tilt); !s.ok())
    return Done(api::FEEDBACK_KIND_FAILED, std::string(s.message()));
  absl::Status status;
  switch (command.action_case()) {
    case api::RobotCommand::kNavigate: {
      goal_yaw_ = command.navigate().goal_yaw();
      recoveries_ = 0;
      absl::StatusOr<FollowPath> follow = ToFollowPath(command.navigate());
      if (follow.ok()) {
        const auto& g = command.navigate().goal();
        navigate_goal_ = follow->waypoints.empty() ? Eigen::Vector3d(g.x(), g.y(), g.z())
                                                   : follow->waypoints.back().position;
      }
      if (!follow.ok())
        return Done(api::FEEDBACK_KIND_FAILED, std::string(follow.status().message()));
      if (follow->waypoints.empty()) {  // already there: only face goal_yaw
        status = robot_.Apply(Rotate{goal_yaw_});
        phase_ = Phase::kFacing;
      } else {
        status = robot_.Apply(*follow);
        phase_ = Phase::kDriving;
      }
      break;
    }
    case api::RobotCommand::kRotate:
      rate_rps_ = command.rotate().angular_speed_rps();
      remaining_s_ = command.rotate().duration_s() > 0 ? command.rotate().duration_s() : -1.0;
      phase_ = Phase::kRotating;
      break;
    case api::RobotCommand::kHold:
      status = robot_.Apply(Hold{});
      remaining_s_ = command.hold().duration_s() > 0 ? command.hold().duration_s() : -1.0;
      phase_ = Phase::kHolding;
      break;
    case api::RobotCommand::kStop:
      // An emergency stop only halts; a task's stop is the agent's final stop action.
      status = command.stop().emergency() ? robot_.Apply(Hold{}) : robot_.Apply(Stop{});
      phase_ = Phase::kIdle;
      break;
    default:
      return Done(api::FEEDBACK_KIND_FAILED, "command without an action");
  }
  if (!status.ok()) return Done(api::FEEDBACK_KIND_FAILED, std::string(status.message()));
  return Feedback{command_id_, api::FEEDBACK_KIND_ACCEPTED, ""};
}

std::optional<Feedback> CommandExecutor::Step(double dt) {
  if (phase_ == Phase::kRotating) {
    const double turn = rate_rps_ * (remaining_s_ < 0 ? dt : std::min(dt, remaining_s_));
    if (absl::Status s = robot_.Apply(Rotate{robot_.pose().yaw + turn}); !s.ok()) {
      robot_.Step(dt);
      return Done(api::FEEDBACK_KIND_FAILED, std::string(s.message()));
    }
  }
  // Re-plan a local path as the map grows: unknown space it crossed may turn out blocked.
  if (phase_ == Phase::kDriving && local_goal_.has_value() &&
      (since_plan_s_ += dt) >= kReplanPeriodS) {
    since_plan_s_ = 0.0;
    absl::StatusOr<FollowPath> follow = PlanLocally(robot_.pose().position, *local_goal_);
    if (follow.ok() && !follow->waypoints.empty()) robot_.Apply(*follow).IgnoreError();
  }
  const StepReport report = robot_.Step(dt);
  if (report.collision.has_value()) {
    // Where the body was (in the air: at what altitude) says which obstacle a path misjudged.
    const double altitude = report.collision->position.z();
    const std::string detail = absl::StrCat(
        "collision with ", report.collision->kind,
        altitude > 1e-6 ? absl::StrCat(" at ", std::round(altitude * 100) / 100, " m altitude")
                        : std::string());
    if (phase_ == Phase::kDriving &&
        (robot_.modality() == Modality::kFlyRoll ? BackUpThenReport(detail) : Recover())) {
      return std::nullopt;
    }
    return Done(api::FEEDBACK_KIND_BLOCKED, phase_ == Phase::kBackingUp ? blocked_detail_ : detail);
  }
  switch (phase_) {
    case Phase::kDriving:
      if (!report.arrived) return std::nullopt;
      if (absl::Status s = robot_.Apply(Rotate{goal_yaw_}); !s.ok()) {
        return Done(api::FEEDBACK_KIND_FAILED, std::string(s.message()));
      }
      phase_ = Phase::kFacing;
      return std::nullopt;
    case Phase::kFacing:
      if (std::abs(WrapAngle(robot_.pose().yaw - goal_yaw_)) > kFacingTolerance)
        return std::nullopt;
      return Done(api::FEEDBACK_KIND_GOAL_REACHED, "");
    case Phase::kRotating:
    case Phase::kHolding:
      if (remaining_s_ < 0) return std::nullopt;
      remaining_s_ -= dt;
      if (remaining_s_ > 1e-9) return std::nullopt;
      return Done(api::FEEDBACK_KIND_GOAL_REACHED, "");
    case Phase::kBackingUp:
      if (!report.arrived) return std::nullopt;
      return Done(api::FEEDBACK_KIND_BLOCKED, blocked_detail_);
    case Phase::kIdle:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace semnav::sim::loop
