#include "services/reasoning/server/proto_convert.h"

#include <cmath>

#include "google/protobuf/util/time_util.h"
#include "services/common/status/grpc_status.h"
#include "services/reasoning/core/input_limits.h"

namespace semnav::reasoning {
namespace {

void SetVector(const Eigen::Vector3d& v, common::v1::Vector3* out) {
  out->set_x(v.x());
  out->set_y(v.y());
  out->set_z(v.z());
}

}  // namespace

api::TargetSpec ToProto(const TargetSpec& target) {
  api::TargetSpec out;
  out.set_name(target.name);
  out.set_is_room(target.is_room);
  for (const std::string& colour : target.colours) out.add_colours(colour);
  out.set_relation(target.relation);
  out.set_anchor(target.anchor);
  out.set_text(target.text);
  return out;
}

TargetSpec FromProto(const api::TargetSpec& target) {
  TargetSpec out;
  out.name = target.name();
  out.is_room = target.is_room();
  out.colours.assign(target.colours().begin(), target.colours().end());
  out.relation = target.relation();
  out.anchor = target.anchor();
  out.text = target.text();
  return out;
}

api::Subgoal ToProto(const Subgoal& subgoal) {
  api::Subgoal out;
  // SubgoalType values are declared in the same order, one above the core's.
  out.set_type(static_cast<api::SubgoalType>(static_cast<int>(subgoal.type) + 1));
  *out.mutable_target() = ToProto(subgoal.target);
  out.set_distance_m(subgoal.distance_m);
  out.set_duration_s(subgoal.duration_s);
  out.set_reason(subgoal.reason);
  return out;
}

void SetFlyRollModes(api::NavigateAction* navigate) {
  constexpr double kAboveFloorM = 1e-6;
  double previous_z = navigate->path().empty() ? 0.0 : navigate->path(0).position().z();
  for (api::PathWaypoint& w : *navigate->mutable_path()) {
    const double z = w.position().z();
    w.set_mode(z > kAboveFloorM || previous_z > kAboveFloorM ? api::LOCOMOTION_MODE_AIR
                                                             : api::LOCOMOTION_MODE_GROUND);
    previous_z = z;
  }
}

api::RobotCommand ToProto(const RobotCommand& command, uint64_t session_command_id,
                          const std::string& task_id) {
  api::RobotCommand out;
  out.set_command_id(session_command_id);
  out.set_task_id(task_id);
  out.set_reason(command.reason);
  switch (command.kind) {
    case CommandKind::kNavigate: {
      api::NavigateAction* navigate = out.mutable_navigate();
      SetVector(command.goal, navigate->mutable_goal());
      navigate->set_goal_yaw(command.goal_yaw);
      navigate->set_max_speed_mps(command.max_speed);
      for (const Eigen::Vector3d& point : command.path)
        SetVector(point, navigate->add_path()->mutable_position());
      break;
    }
    case CommandKind::kRotate:
      out.mutable_rotate()->set_angular_speed_rps(command.angular_speed);
      out.mutable_rotate()->set_duration_s(command.duration_s);
      out.mutable_rotate()->set_camera_tilt_rad(command.camera_tilt_rad);
      break;
    case CommandKind::kStop:
      out.mutable_stop();
      break;
    case CommandKind::kHold:
      out.mutable_hold()->set_duration_s(command.duration_s);
      out.mutable_hold()->set_camera_tilt_rad(command.camera_tilt_rad);
      break;
  }
  return out;
}

api::Event ToProto(const LoggedEvent& event) {
  api::Event out;
  out.set_event_id(event.id);
  *out.mutable_time() =
      google::protobuf::util::TimeUtil::NanosecondsToTimestamp(absl::ToUnixNanos(event.time));
  out.set_kind(static_cast<api::EventKind>(event.kind));
  out.set_robot_id(event.robot_id);
  out.set_task_id(event.task_id);
  out.set_message(event.message);
  return out;
}

api::TaskStatus ToProto(TaskState state) {
  switch (state) {
    case TaskState::kRunning:
      return api::TASK_STATUS_RUNNING;
    case TaskState::kPaused:
      return api::TASK_STATUS_PAUSED;
    case TaskState::kSucceeded:
      return api::TASK_STATUS_SUCCEEDED;
    case TaskState::kFailed:
      return api::TASK_STATUS_FAILED;
    case TaskState::kCancelled:
      return api::TASK_STATUS_CANCELLED;
  }
  return api::TASK_STATUS_UNSPECIFIED;
}

api::ResolutionPath ToProto(ResolutionPath path) {
  switch (path) {
    case ResolutionPath::kFast:
      return api::RESOLUTION_PATH_FAST;
    case ResolutionPath::kSlow:
      return api::RESOLUTION_PATH_SLOW;
  }
  return api::RESOLUTION_PATH_UNSPECIFIED;
}

std::optional<ExplorationStrategy> StrategyFromProto(api::ExplorationStrategy strategy) {
  switch (strategy) {
    case api::EXPLORATION_STRATEGY_NEAREST_FRONTIER:
      return ExplorationStrategy::kNearestFrontier;
    case api::EXPLORATION_STRATEGY_COVERAGE_MAX:
      return ExplorationStrategy::kCoverageMax;
    case api::EXPLORATION_STRATEGY_SEMANTIC_FRONTIER:
      return ExplorationStrategy::kSemanticFrontier;
    case api::EXPLORATION_STRATEGY_EROI_UTILITY:
      return ExplorationStrategy::kEroiUtility;
    default:
      return std::nullopt;
  }
}

api::TaskSnapshot ToProto(const TaskView& view) {
  using google::protobuf::util::TimeUtil;
  api::TaskSnapshot out;
  out.set_task_id(view.task_id);
  out.set_robot_id(view.robot_id);
  out.set_instruction(view.instruction);
  out.set_status(view.pending ? api::TASK_STATUS_PENDING : ToProto(view.state));
  out.set_revision(view.revision);
  for (const Subgoal& goal : view.subgoals) *out.add_subgoals() = ToProto(goal);
  out.set_current_subgoal(view.current_subgoal);
  out.set_phase(view.phase);
  out.set_reason(view.reason);
  if (view.target.has_value()) {
    api::ResolvedTarget* target = out.mutable_target();
    target->set_object_id(view.target->object_id);
    SetVector(view.target->position, target->mutable_position());
    target->set_confidence(view.target->confidence);
    target->set_path(ToProto(view.target->path));
  }
  for (const Eigen::Vector3d& point : view.path) SetVector(point, out.add_path());
  out.set_progress(view.progress);
  out.set_decomposition_source(view.decomposition_source);
  out.set_replans(view.replans);
  out.set_explore_goals(view.explore_goals);
  out.set_model_requests(view.model_requests);
  out.set_model_calls(view.model_calls);
  if (view.exploration_strategy.has_value()) {
    out.set_exploration_strategy(std::string(ExplorationStrategyName(*view.exploration_strategy)));
  }
  if (view.search_area.has_value()) *out.mutable_search_area() = ToProto(*view.search_area);
  *out.mutable_created_at() = TimeUtil::NanosecondsToTimestamp(absl::ToUnixNanos(view.created));
  *out.mutable_updated_at() = TimeUtil::NanosecondsToTimestamp(absl::ToUnixNanos(view.updated));
  return out;
}

RobotPose FromProto(const api::RobotState& state) { return FromProto(state.pose()); }

RobotPose FromProto(const common::v1::Pose& p) {
  RobotPose pose;
  pose.position = Eigen::Vector3d(p.position().x(), p.position().y(), p.position().z());
  const common::v1::Quaternion& q = p.orientation();
  pose.yaw = std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                        1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
  return pose;
}

common::v1::Pose ToProtoPose(const RobotPose& pose) {
  common::v1::Pose out;
  out.mutable_position()->set_x(pose.position.x());
  out.mutable_position()->set_y(pose.position.y());
  out.mutable_position()->set_z(pose.position.z());
  out.mutable_orientation()->set_z(std::sin(pose.yaw / 2.0));
  out.mutable_orientation()->set_w(std::cos(pose.yaw / 2.0));
  return out;
}

absl::StatusOr<SearchArea> FromProto(const api::SearchArea& area) {
  const SearchArea out{Eigen::Vector2d(area.min_x(), area.min_y()),
                       Eigen::Vector2d(area.max_x(), area.max_y())};
  if (absl::Status status = CheckSearchArea(out, "search_area"); !status.ok()) return status;
  return out;
}

api::SearchArea ToProto(const SearchArea& area) {
  api::SearchArea out;
  out.set_min_x(area.min.x());
  out.set_min_y(area.min.y());
  out.set_max_x(area.max.x());
  out.set_max_y(area.max.y());
  return out;
}

std::optional<RobotFeedback> FromProto(api::FeedbackKind kind) {
  switch (kind) {
    case api::FEEDBACK_KIND_GOAL_REACHED:
      return RobotFeedback::kGoalReached;
    case api::FEEDBACK_KIND_FAILED:
      return RobotFeedback::kFailed;
    case api::FEEDBACK_KIND_BLOCKED:
      return RobotFeedback::kBlocked;
    default:
      return std::nullopt;
  }
}

}  // namespace semnav::reasoning
