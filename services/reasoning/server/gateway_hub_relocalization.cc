// GatewayHub: the relocalization loop of each robot (core/relocalization_loop.h) run against
// the robot's session, its task and the relocalization service.
#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "services/common/logging/log.h"
#include "services/common/status/field_error.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_internal.h"
#include "services/reasoning/server/proto_convert.h"
#include "services/reasoning/server/request_checks.h"

namespace semnav::reasoning {

using namespace hub_internal;

namespace {

LocalizationReport ReportOf(api::LocalizationStatus status) {
  switch (status) {
    case api::LOCALIZATION_STATUS_LOST:
      return LocalizationReport::kLost;
    case api::LOCALIZATION_STATUS_UNCERTAIN:
      return LocalizationReport::kUncertain;
    default:
      return LocalizationReport::kOk;  // UNSPECIFIED (robots without the field) = OK
  }
}

bool IsIdentity(const PlanarTransform& t) { return t.translation.isZero(0.0) && t.yaw == 0.0; }

}  // namespace

bool GatewayHub::PoseTrusted(const Robot& robot) const {
  return robot.localization == nullptr ||
         (!robot.localization->relocalizing() && robot.localization->trusted());
}

bool GatewayHub::MayCommand(const Robot& robot, const RobotCommand& command) const {
  // Stops and holds are always safe; motion waits for a trusted pose.
  return PoseTrusted(robot) || command.kind == CommandKind::kStop ||
         command.kind == CommandKind::kHold;
}

RobotCommand GatewayHub::InRobotFrame(const Robot& robot, const RobotCommand& command) const {
  if (robot.localization == nullptr || command.kind != CommandKind::kNavigate) return command;
  const PlanarTransform odom_from_map = robot.localization->map_from_odom().Inverse();
  RobotCommand out = command;
  out.goal = odom_from_map.Apply(command.goal);
  out.goal_yaw = std::remainder(command.goal_yaw + odom_from_map.yaw, 2.0 * M_PI);
  for (Eigen::Vector3d& point : out.path) point = odom_from_map.Apply(point);
  return out;
}

void GatewayHub::OnLocalizationSession(Robot& robot) {
  if (backends_.relocalizer == nullptr) return;
  // A simulated session is a new simulation: its odometry and map start over, and so does the
  // correction. A real robot that reconnects keeps its odometry frame and its correction.
  if (robot.localization == nullptr || robot.simulated_clock) {
    RelocalizationLoopConfig loop = config_.relocalization.loop;
    loop.refine_with_scan = loop.refine_with_scan && backends_.lost_scan != nullptr;
    robot.localization = std::make_unique<RelocalizationLoop>(loop);
    robot.localization_paused_task.clear();
  }
  robot.localization->OnSessionOpened();
  robot.localization->SetLimits(robot.capabilities.max_linear_speed_mps(),
                                robot.capabilities.max_angular_speed_rps());
  if (!IsIdentity(robot.localization->map_from_odom())) SendLocalizationUpdate(robot);
}

api::RobotLocalization GatewayHub::LocalizationOf(const Robot& robot) const {
  api::RobotLocalization out;
  out.set_reported(robot.last_state.localization());
  const PlanarTransform correction =
      robot.localization != nullptr ? robot.localization->map_from_odom() : PlanarTransform{};
  *out.mutable_map_from_odom() = ToProtoPose(RobotPose{correction.translation, correction.yaw});
  *out.mutable_map_pose() = ToProtoPose(robot.pose);
  out.set_relocalizing(robot.localization != nullptr && robot.localization->relocalizing());
  out.set_trusted(robot.localization == nullptr || robot.localization->trusted());
  if (robot.localization != nullptr) {
    out.set_recoveries(static_cast<uint32_t>(robot.localization->recoveries()));
    out.set_failures(static_cast<uint32_t>(robot.localization->failures()));
    out.set_trigger(robot.localization->trigger());
  }
  return out;
}

void GatewayHub::SendLocalizationUpdate(Robot& robot) {
  if (robot.session == nullptr || robot.localization == nullptr) return;
  api::ConnectResponse update;
  const PlanarTransform& correction = robot.localization->map_from_odom();
  *update.mutable_localization()->mutable_map_from_odom() =
      ToProtoPose(RobotPose{correction.translation, correction.yaw});
  update.mutable_localization()->set_relocalizing(robot.localization->relocalizing());
  robot.session->Send(update);
}

bool GatewayHub::TrackLocalization(const std::string& robot_id, Robot& robot,
                                   const api::RobotState& state, const RobotPose& odom_pose) {
  if (backends_.relocalizer == nullptr) {
    robot.pose = odom_pose;
    return true;
  }
  if (robot.localization == nullptr) OnLocalizationSession(robot);
  const Task* task = tasks_.Find(robot.active_task);
  const bool task_running =
      task != nullptr && task->started && task->executor->progress().state == TaskState::kRunning;
  const bool was_relocalizing = robot.localization->relocalizing();
  std::vector<RelocalizationAction> actions = robot.localization->OnState(
      NowFor(robot_id), odom_pose, ReportOf(state.localization()), *scene_graph_, task_running);
  robot.pose = robot.localization->map_from_odom().Apply(odom_pose);
  RunLocalizationActions(robot_id, robot, std::move(actions));
  robot.pose =
      robot.localization->map_from_odom().Apply(odom_pose);  // a correction applies at once
  if (was_relocalizing != robot.localization->relocalizing()) SendLocalizationUpdate(robot);
  return PoseTrusted(robot);
}

void GatewayHub::RunLocalizationActions(const std::string& robot_id, Robot& robot,
                                        std::vector<RelocalizationAction> actions) {
  using Kind = RelocalizationAction::Kind;
  Task* task = SettledActiveTask(robot);  // never act on an executor inside a planning call
  Task* active = task != nullptr && task->started && !task->executor->finished() ? task : nullptr;
  const std::string task_id = active != nullptr ? active->task_id : "";
  for (RelocalizationAction& action : actions) {
    switch (action.kind) {
      case Kind::kPauseTask:
        Log(api::EVENT_KIND_RELOCALIZING, robot_id, task_id, action.message);
        if (active != nullptr && active->executor->progress().state == TaskState::kRunning) {
          robot.localization_paused_task = active->task_id;
          Apply(*active, active->executor->Pause());
        }
        break;
      case Kind::kCommand: {
        if (robot.session == nullptr) break;
        api::ConnectResponse response;
        robot.last_session_command = robot.next_command_id++;
        robot.last_executor_command =
            action.command.id;  // not the executor's: its feedback is ignored there
        *response.mutable_command() = ToProto(action.command, robot.last_session_command, task_id);
        robot.last_command = response.command();
        robot.session->Send(response);
        break;
      }
      case Kind::kRelocalize: {
        const std::string map_id =
            config_.relocalization.map_id.empty() ? robot_id : config_.relocalization.map_id;
        std::function<void(absl::StatusOr<RelocalizationAnswer>)> handler =
            LoopCallback(robot, robot_id, &RelocalizationLoop::OnAnswer);
        std::string observed;  // for the log: what the turn saw, in the robot's odometry frame
        for (const ObservedObject& o : action.observed) {
          const SceneObject* seen = scene_graph_->FindObject(o.object_id);
          absl::StrAppend(&observed, o.object_id, seen != nullptr ? ":" + seen->label : "", "@(",
                          absl::StrFormat("%.2f,%.2f", o.position.x(), o.position.y()), ") s",
                          absl::StrFormat("%.2f", o.scale_m), " n", o.observations, "; ");
        }
        LogWarning("relocalization_request",
                   {{"robot", robot_id}, {"map_id", map_id}, {"observed", observed}});
        backends_.relocalizer->Relocalize(map_id, action.observed, std::move(handler));
        break;
      }
      case Kind::kRefine: {
        std::function<void(absl::StatusOr<ScanRefinement>)> handler =
            LoopCallback(robot, robot_id, &RelocalizationLoop::OnRefinement);
        std::optional<PlanarTransform> coarse;
        if (!action.global) coarse = action.map_from_odom;
        LogWarning(
            "scan_refinement_request",
            {{"robot", robot_id},
             {"coarse", coarse.has_value()
                            ? absl::StrFormat("(%.3f, %.3f, %.2f deg)", coarse->translation.x(),
                                              coarse->translation.y(), coarse->yaw * 180.0 / M_PI)
                            : std::string("none: global")}});
        backends_.lost_scan->MatchLostScan(robot_id, coarse, std::move(handler));
        break;
      }
      case Kind::kCorrect:
        Log(api::EVENT_KIND_RELOCALIZED, robot_id, task_id, action.message);
        break;
      case Kind::kResumeTask:
        if (active != nullptr && robot.localization_paused_task == active->task_id &&
            active->executor->progress().state == TaskState::kPaused &&
            !active->paused_by_session) {
          Apply(*active, active->executor->OnPose(NowFor(robot_id),
                                                  robot.pose));  // paused: only takes the pose
          Apply(*active, active->executor->Resume(NowFor(robot_id)));
        }
        robot.localization_paused_task.clear();
        break;
      case Kind::kFailTask:
        Log(api::EVENT_KIND_RELOCALIZATION_FAILED, robot_id, task_id, action.message);
        if (active != nullptr) Apply(*active, active->executor->Abandon(action.message));
        robot.localization_paused_task.clear();
        break;
    }
  }
}

template <typename Answer>
std::function<void(absl::StatusOr<Answer>)> GatewayHub::LoopCallback(
    Robot& robot, const std::string& robot_id,
    std::vector<RelocalizationAction> (RelocalizationLoop::*deliver)(
        double, const absl::StatusOr<Answer>&)) {
  auto to_loop = [this, robot_id, deliver](absl::StatusOr<Answer> answer) {
    OnLocalizationAnswer(robot_id, [&answer, deliver](RelocalizationLoop& loop, double now) {
      return (loop.*deliver)(now, answer);
    });
  };
  if (!robot.simulated_clock) return to_loop;
  // Held like a model answer (AtSimulatedArrival): the step waits for the call and applies the
  // answer at issue time + the configured latency, so episodes replay exactly.
  ++robot.model_calls_in_flight;
  return [this, robot_id, to_loop,
          due = robot.sim_now_s + config_.relocalization.simulated_latency_s,
          order = next_model_call_++](absl::StatusOr<Answer> answer) {
    absl::MutexLock lock(&mu_);
    Robot& arrived = RobotRecord(robot_id);
    --arrived.model_calls_in_flight;
    arrived.held_answers.push_back({due, order, [to_loop, answer = std::move(answer)]() mutable {
                                      to_loop(std::move(answer));
                                    }});
  };
}

void GatewayHub::OnLocalizationAnswer(
    const std::string& robot_id,
    const std::function<std::vector<RelocalizationAction>(RelocalizationLoop&, double now)>&
        event) {
  absl::MutexLock lock(&mu_);
  if (shut_down_) return;
  auto found = robots_.find(robot_id);
  if (found == robots_.end() || found->second.localization == nullptr) return;
  Robot& robot = found->second;
  const bool was_relocalizing = robot.localization->relocalizing();
  std::vector<RelocalizationAction> actions = event(*robot.localization, NowFor(robot_id));
  const bool acted = !actions.empty();
  const RobotPose odom_pose = FromProto(robot.last_state);
  robot.pose =
      robot.localization->map_from_odom().Apply(odom_pose);  // before the task resumes on it
  RunLocalizationActions(robot_id, robot, std::move(actions));
  if (was_relocalizing != robot.localization->relocalizing() || acted)
    SendLocalizationUpdate(robot);
}

absl::StatusOr<api::RelocalizeRobotResponse> GatewayHub::RelocalizeRobot(
    const api::RelocalizeRobotRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.request_id(), "request_id"); !s.ok()) return s;
  if (absl::Status s = Required(request.robot_id(), "robot_id"); !s.ok()) return s;
  const std::string key = absl::StrCat("RelocalizeRobot:", request.request_id());
  if (auto cached = Cached<api::RelocalizeRobotResponse>(requests_, key)) return *cached;
  auto found = robots_.find(request.robot_id());
  if (found == robots_.end()) {
    return FieldError(absl::StatusCode::kNotFound, "robot_id", "unknown robot", "NOT_FOUND");
  }
  if (absl::Status s = CheckControl(request.robot_id(), request.lease_id()); !s.ok()) return s;
  Robot& robot = found->second;
  if (backends_.relocalizer == nullptr) {
    return FieldError(absl::StatusCode::kFailedPrecondition, "robot_id",
                      "no relocalization service is configured (gateway.relocalization.address)",
                      "RELOCALIZATION_UNAVAILABLE");
  }
  if (robot.session == nullptr) {
    return FieldError(absl::StatusCode::kFailedPrecondition, "robot_id",
                      "the robot's session is down", "RELOCALIZATION_UNAVAILABLE");
  }
  if (robot.localization == nullptr) OnLocalizationSession(robot);
  const bool was_relocalizing = robot.localization->relocalizing();
  RunLocalizationActions(
      request.robot_id(), robot,
      robot.localization->OnRequest(NowFor(request.robot_id()), request.reason(), *scene_graph_));
  if (was_relocalizing != robot.localization->relocalizing()) SendLocalizationUpdate(robot);
  api::RelocalizeRobotResponse response;
  *response.mutable_localization() = LocalizationOf(robot);
  requests_.Remember(key, response.SerializeAsString());
  return response;
}

}  // namespace semnav::reasoning
