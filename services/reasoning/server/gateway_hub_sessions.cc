// GatewayHub: robot sessions (hello, state, feedback, loss).
#include "services/reasoning/server/gateway_hub.h"

#include "absl/strings/str_cat.h"
#include "services/reasoning/server/hub_internal.h"
#include "services/reasoning/server/proto_convert.h"
#include "services/reasoning/server/request_checks.h"

namespace semnav::reasoning {

using namespace hub_internal;

absl::StatusOr<api::SessionAccepted> GatewayHub::OpenSession(const api::SessionHello& hello,
                                                             StreamSink<api::ConnectResponse>* sink) {
  absl::MutexLock lock(&mu_);
  if (shut_down_) return absl::UnavailableError("gateway shutting down");
  if (absl::Status s = Validate(hello); !s.ok()) return s;
  Robot& robot = RobotRecord(hello.robot_id());
  if (robot.session != nullptr && robot.session != sink) {
    robot.session->Close(grpc::Status(grpc::StatusCode::ABORTED, "replaced by a new session"));
  }
  robot.session = sink;
  robot.capabilities = hello.capabilities();
  api::SessionAccepted accepted;
  accepted.set_session_id(absl::StrCat(hello.robot_id(), "-", robot.next_command_id));
  Log(api::EVENT_KIND_SESSION, hello.robot_id(), "", "session opened");
  api::ConnectResponse first;
  auto task = tasks_.find(robot.active_task);
  if (task != tasks_.end() && (task->second.paused_by_session || task->second.resume_on_state)) {
    accepted.set_resumed_task_id(task->first);
  }
  *first.mutable_accepted() = accepted;
  sink->Send(first);
  if (task != tasks_.end() && !task->second.executor->finished()) {
    if (task->second.paused_by_session) {
      task->second.paused_by_session = false;
      SetMobility(task->second, robot);  // the robot may come back with other capabilities
      Apply(task->second, task->second.executor->Resume(Now()));
    } else {
      StartIfPossible(task->second);
    }
  }
  return accepted;
}

GatewayHub::Robot* GatewayHub::RobotOfSink(StreamSink<api::ConnectResponse>* sink, std::string* robot_id) {
  for (auto& [id, robot] : robots_) {
    if (robot.session == sink) {
      *robot_id = id;
      return &robot;
    }
  }
  return nullptr;
}

absl::Status GatewayHub::OnRobotState(StreamSink<api::ConnectResponse>* sink,
                                      const api::RobotState& state) {
  // Checked before anything is stored: the last good pose stays and no command is built.
  absl::StatusOr<RobotPose> pose = ValidatedPose(state);
  if (!pose.ok()) return pose.status();
  absl::MutexLock lock(&mu_);
  std::string robot_id;
  Robot* robot = RobotOfSink(sink, &robot_id);
  if (robot == nullptr) return absl::OkStatus();
  robot->pose = *pose;
  robot->last_state = state;
  std::vector<std::string> nearby;
  for (const SceneObject& object : scene_graph_.objects) {
    if ((object.position - robot->pose.position).head<2>().norm() <= config_.memory_label_radius_m) {
      nearby.push_back(object.label);
    }
  }
  robot->memory->Update(robot->pose.position, nearby, {});
  const absl::Time now = absl::Now();
  for (auto& [watcher, subscription] : fast_watchers_) {
    if (subscription.robot_id != robot_id || now - subscription.last_sent < subscription.interval) continue;
    subscription.last_sent = now;
    api::StreamFastTelemetryResponse sample;
    *sample.mutable_state() = state;
    sample.set_task_id(robot->active_task);
    *sample.mutable_last_command() = robot->last_command;
    watcher->Send(sample);
  }
  auto task = tasks_.find(robot->active_task);
  if (task != tasks_.end() && task->second.resume_on_state) {
    // Restored after a gateway crash: this is the first pose the gateway can trust.
    task->second.resume_on_state = false;
    SetMobility(task->second, *robot);
    Apply(task->second, task->second.executor->OnPose(Now(), robot->pose));  // paused: only takes the pose
    Apply(task->second, task->second.executor->Resume(Now()));
  } else if (task != tasks_.end() && task->second.started) {
    Apply(task->second, task->second.executor->OnPose(Now(), robot->pose));
  }
  return absl::OkStatus();
}

absl::Status GatewayHub::OnFeedback(StreamSink<api::ConnectResponse>* sink,
                                    const api::CommandFeedback& feedback) {
  if (absl::Status s = Validate(feedback); !s.ok()) return s;
  absl::MutexLock lock(&mu_);
  std::string robot_id;
  Robot* robot = RobotOfSink(sink, &robot_id);
  const std::optional<RobotFeedback> kind = FromProto(feedback.kind());
  const bool current = robot != nullptr && feedback.command_id() == robot->last_session_command;
  if (!current || !kind.has_value()) return absl::OkStatus();
  auto task = tasks_.find(robot->active_task);
  if (task == tasks_.end() || !task->second.started) return absl::OkStatus();
  Apply(task->second, task->second.executor->OnFeedback(Now(), robot->last_executor_command, *kind));
  return absl::OkStatus();
}

void GatewayHub::CloseSession(StreamSink<api::ConnectResponse>* sink) {
  absl::MutexLock lock(&mu_);
  std::string robot_id;
  Robot* robot = RobotOfSink(sink, &robot_id);
  if (robot == nullptr) return;
  robot->session = nullptr;
  Log(api::EVENT_KIND_SESSION, robot_id, "", "session closed");
  auto task = tasks_.find(robot->active_task);
  // A task waiting for planning pauses for the session too, so the robot's return resumes it.
  if (task == tasks_.end() || !task->second.started ||
      (task->second.executor->progress().state != TaskState::kRunning &&
       !task->second.executor->waiting_for_dependency())) {
    return;
  }
  task->second.paused_by_session = true;
  Apply(task->second, task->second.executor->Pause());
}

}  // namespace semnav::reasoning
