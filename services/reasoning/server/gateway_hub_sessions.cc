// GatewayHub: robot sessions (hello, state, feedback, loss).
#include <algorithm>
#include <tuple>

#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/common/status/field_error.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_internal.h"
#include "services/reasoning/server/proto_convert.h"
#include "services/reasoning/server/request_checks.h"

namespace semnav::reasoning {

using namespace hub_internal;

namespace {

// Wall time a simulated-clock state may wait for the scene graph or for model answers; beyond it
// the step goes on with what is there and a warning says the episode may not replay.
constexpr absl::Duration kSimulatedStepWait = absl::Seconds(30);
// Simulated stamps: at least 0 and at most about 31 years of simulation.
constexpr int64_t kMaxSimulatedSeconds = int64_t{1} << 30;

absl::StatusOr<double> SimulatedSeconds(const api::RobotState& state) {
  const google::protobuf::Timestamp& stamp = state.header().stamp();
  if (stamp.seconds() < 0 || stamp.seconds() > kMaxSimulatedSeconds || stamp.nanos() < 0 ||
      stamp.nanos() > 999999999) {
    return InvalidField("state.header.stamp", "must be a simulated time in [0, 2^30] s");
  }
  return static_cast<double>(stamp.seconds()) + stamp.nanos() * 1e-9;
}

// A robot that can fly (AIR or FLY_ROLL) sees wide; the rest, and an empty list ("GROUND
// only"), are ground robots.
RobotPlatform PlatformOf(const google::protobuf::RepeatedField<int>& modes) {
  for (int mode : modes) {
    if (mode == api::LOCOMOTION_MODE_AIR || mode == api::LOCOMOTION_MODE_FLY_ROLL) {
      return RobotPlatform::kAerial;
    }
  }
  return RobotPlatform::kGround;
}

}  // namespace

void GatewayHub::SetSceneGraphSync(std::function<absl::Status(absl::Duration timeout)> sync) {
  absl::MutexLock lock(&mu_);
  scene_sync_ = std::move(sync);
}

double GatewayHub::NowFor(const std::string& robot_id) {
  auto robot = robots_.find(robot_id);
  return robot != robots_.end() && robot->second.simulated_clock ? robot->second.sim_now_s : Now();
}

absl::StatusOr<api::SessionAccepted> GatewayHub::OpenSession(
    const api::SessionHello& hello, StreamSink<api::ConnectResponse>* sink) {
  absl::MutexLock lock(&mu_);
  if (shut_down_) return absl::UnavailableError("gateway shutting down");
  if (absl::Status s = Validate(hello); !s.ok()) return s;
  if (!api::ClockKind_IsValid(hello.clock())) {
    return InvalidField("hello.clock", absl::StrCat("unknown value ", hello.clock()));
  }
  Robot& robot = RobotRecord(hello.robot_id());
  SettledActiveTask(robot);  // before anything changes: waiting releases mu_
  if (shut_down_) return absl::UnavailableError("gateway shutting down");
  if (robot.session != nullptr && robot.session != sink) {
    robot.session->Close(grpc::Status(grpc::StatusCode::ABORTED, "replaced by a new session"));
  }
  robot.session = sink;
  robot.capabilities = hello.capabilities();
  const auto& modes = hello.capabilities().modes();
  robot.fly_roll =
      std::find(modes.begin(), modes.end(), api::LOCOMOTION_MODE_FLY_ROLL) != modes.end();
  robot.footprint_radius_m = hello.capabilities().footprint_radius_m();
  robot.camera_tilt_max_rad = hello.capabilities().camera_tilt_max_rad();
  robot.platform = PlatformOf(modes);
  robot.simulated_clock = hello.clock() == api::CLOCK_KIND_SIMULATED;
  // A new simulated session is a new simulation: its clock and frames start over.
  robot.sim_now_s = 0.0;
  robot.synced_mapping_revision = 0;
  robot.step_inputs.clear();
  OnLocalizationSession(robot);
  api::SessionAccepted accepted;
  accepted.set_session_id(absl::StrCat(hello.robot_id(), "-", robot.next_command_id));
  Log(api::EVENT_KIND_SESSION, hello.robot_id(), "", "session opened");
  api::ConnectResponse first;
  Task* task = tasks_.Find(robot.active_task);
  if (task != nullptr && (task->paused_by_session || task->resume_on_state)) {
    accepted.set_resumed_task_id(task->task_id);
  }
  *first.mutable_accepted() = accepted;
  sink->Send(first);
  if (task != nullptr && !task->executor->finished()) {
    if (task->paused_by_session) {
      task->paused_by_session = false;
      SetMobility(*task, robot);  // the robot may come back with other capabilities
      Apply(*task, task->executor->Resume(NowFor(task->robot_id)));
    } else {
      StartIfPossible(*task);
    }
  }
  return accepted;
}

GatewayHub::Robot* GatewayHub::RobotOfSink(StreamSink<api::ConnectResponse>* sink,
                                           std::string* robot_id) {
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
  {
    absl::MutexLock lock(&mu_);
    std::string robot_id;
    Robot* robot = RobotOfSink(sink, &robot_id);
    if (robot == nullptr) return absl::OkStatus();
    if (!robot->simulated_clock) {
      HandlePose(robot_id, *robot, state, *pose);
      return absl::OkStatus();
    }
  }
  return OnSimulatedStep(sink, state, *pose);
}

absl::Status GatewayHub::OnSimulatedStep(StreamSink<api::ConnectResponse>* sink,
                                         const api::RobotState& state, const RobotPose& pose) {
  absl::StatusOr<double> now = SimulatedSeconds(state);
  if (!now.ok()) return now.status();
  std::function<absl::Status(absl::Duration)> sync;
  {
    absl::MutexLock lock(&mu_);
    std::string robot_id;
    Robot* robot = RobotOfSink(sink, &robot_id);
    if (robot == nullptr) return absl::OkStatus();
    if (*now < robot->sim_now_s) {
      return InvalidField(
          "state.header.stamp",
          absl::StrCat("simulated time went back from ", robot->sim_now_s, " s to ", *now, " s"));
    }
    if (state.mapping_revision() > robot->synced_mapping_revision) sync = scene_sync_;
  }
  // Outside the lock: the fetched graph comes in through OnSceneGraph. Mapping holds still
  // meanwhile (the robot sends no frame before StepDone), so the graph is the one of its frame.
  if (sync) {
    if (absl::Status synced = sync(kSimulatedStepWait); !synced.ok()) {
      LogWarning("simulated_step_scene_graph_unsynced",
                 {{"mapping_revision", static_cast<int64_t>(state.mapping_revision())},
                  {"message", synced.message()}});
    }
  }
  absl::MutexLock lock(&mu_);
  std::string robot_id;
  Robot* robot = RobotOfSink(sink, &robot_id);
  if (robot == nullptr) return absl::OkStatus();
  robot->sim_now_s = *now;
  robot->synced_mapping_revision =
      std::max(robot->synced_mapping_revision, state.mapping_revision());
  ApplyDueAnswers(robot_id);
  robot = RobotOfSink(sink, &robot_id);  // handlers ran without the lock
  if (robot == nullptr) return absl::OkStatus();
  // The graph a task knows changes only here, so every step sees the graph of its own frame.
  Task* task = SettledActiveTask(*robot);
  if (task != nullptr && task->graph_revision != scene_graph_->revision) {
    std::vector<RobotCommand> commands = GiveSceneGraph(*task, *now);
    if (task->started) Apply(*task, commands);
  }
  std::vector<api::ConnectRequest> inputs = std::move(robot->step_inputs);
  robot->step_inputs.clear();
  for (const api::ConnectRequest& input : inputs) {
    if (input.has_feedback()) {
      HandleFeedback(*robot, input.feedback());
    } else if (absl::Status s = HandleCameraFrame(robot_id, *robot, input.camera()); !s.ok()) {
      LogWarning("camera_frame_rejected", {{"message", s.message()}});
    }
  }
  HandlePose(robot_id, *robot, state, pose);
  api::ConnectResponse done;
  done.mutable_step_done()->set_step(state.step());
  if (robot->session != nullptr) robot->session->Send(done);
  return absl::OkStatus();
}

void GatewayHub::ApplyDueAnswers(const std::string& robot_id) {
  const absl::Time deadline = absl::Now() + kSimulatedStepWait;
  bool waited_out = false;
  while (true) {
    // Every call's latency is known only when its answer is back: wait for all of them, so
    // which answers are due does not depend on how fast the model answered in wall time.
    auto settled = [this, &robot_id]() ABSL_SHARED_LOCKS_REQUIRED(mu_) {
      auto robot = robots_.find(robot_id);
      return shut_down_ || robot == robots_.end() || robot->second.model_calls_in_flight == 0;
    };
    if (!waited_out && !mu_.AwaitWithDeadline(absl::Condition(&settled), deadline)) {
      waited_out = true;
      LogWarning("simulated_step_model_wait_exceeded", {{"robot", robot_id}});
    }
    Robot& robot = RobotRecord(robot_id);
    std::vector<HeldAnswer> due;
    std::vector<HeldAnswer> later;
    for (HeldAnswer& held : robot.held_answers) {
      (held.due_s <= robot.sim_now_s ? due : later).push_back(std::move(held));
    }
    robot.held_answers = std::move(later);
    if (due.empty() || shut_down_) return;
    std::sort(due.begin(), due.end(), [](const HeldAnswer& a, const HeldAnswer& b) {
      return std::tie(a.due_s, a.order) < std::tie(b.due_s, b.order);
    });
    mu_.Unlock();  // the handlers take mu_
    for (HeldAnswer& held : due) held.apply();
    mu_.Lock();
  }
}

void GatewayHub::HandlePose(const std::string& robot_id, Robot& robot, const api::RobotState& state,
                            const RobotPose& pose) {
  Task* const task = SettledActiveTask(robot);
  robot.last_state = state;
  const bool pose_trusted =
      TrackLocalization(robot_id, robot, state, pose);  // sets robot.pose (map frame)
  std::vector<std::string> nearby;
  for (const SceneObject& object : scene_graph_->objects) {
    if ((object.position - robot.pose.position).head<2>().norm() <= config_.memory_label_radius_m) {
      nearby.push_back(object.label);
    }
  }
  robot.memory->Update(robot.pose.position, nearby, {});
  for (StreamSink<api::StreamFastTelemetryResponse>* watcher :
       fast_watchers_.TakeDue(robot_id, absl::Now())) {
    api::StreamFastTelemetryResponse sample;
    *sample.mutable_state() = state;
    sample.set_task_id(robot.active_task);
    *sample.mutable_last_command() = robot.last_command;
    *sample.mutable_localization() = LocalizationOf(robot);
    watcher->Send(sample);
  }
  if (!pose_trusted) return;  // the task waits for relocalization
  if (task != nullptr && task->resume_on_state) {
    // Restored after a gateway crash: this is the first pose the gateway can trust.
    task->resume_on_state = false;
    SetMobility(*task, robot);
    Apply(*task,
          task->executor->OnPose(NowFor(robot_id), robot.pose));  // paused: only takes the pose
    Apply(*task, task->executor->Resume(NowFor(robot_id)));
  } else if (task != nullptr && task->started) {
    // A graph that came while the task was inside a planning call (OnSceneGraph skipped it).
    if (!robot.simulated_clock && task->graph_revision != scene_graph_->revision) {
      Apply(*task, GiveSceneGraph(*task, NowFor(robot_id)));
    }
    // Clues the robot reached while still searching have failed (EroiSearch::OnRobotAt).
    if (EroiSearch* search = task->eroi.get(); search != nullptr && task->executor->exploring()) {
      const bool was_geometric = search->geometric();
      search->OnRobotAt(robot.pose.position);
      if (search->geometric() && !was_geometric) {
        Log(api::EVENT_KIND_TASK_STATUS, robot_id, task->task_id,
            absl::StrCat("search turned geometric: the robot reached ", search->failed_clues(),
                         " of the model's clues without finding the target"));
      }
    }
    Apply(*task, task->executor->OnPose(NowFor(robot_id), robot.pose));
  }
}

absl::Status GatewayHub::OnFeedback(StreamSink<api::ConnectResponse>* sink,
                                    const api::CommandFeedback& feedback) {
  if (absl::Status s = Validate(feedback); !s.ok()) return s;
  absl::MutexLock lock(&mu_);
  std::string robot_id;
  Robot* robot = RobotOfSink(sink, &robot_id);
  if (robot == nullptr) return absl::OkStatus();
  if (robot->simulated_clock) {  // handled with the step's state, at its time
    api::ConnectRequest input;
    *input.mutable_feedback() = feedback;
    robot->step_inputs.push_back(std::move(input));
    return absl::OkStatus();
  }
  HandleFeedback(*robot, feedback);
  return absl::OkStatus();
}

void GatewayHub::HandleFeedback(Robot& robot, const api::CommandFeedback& feedback) {
  const std::optional<RobotFeedback> kind = FromProto(feedback.kind());
  Task* const task =
      SettledActiveTask(robot);  // its planning call may send the command this refers to
  if (feedback.command_id() != robot.last_session_command || !kind.has_value()) return;
  if (task == nullptr || !task->started) return;
  Apply(*task,
        task->executor->OnFeedback(NowFor(task->robot_id), robot.last_executor_command, *kind));
}

void GatewayHub::CloseSession(StreamSink<api::ConnectResponse>* sink) {
  absl::MutexLock lock(&mu_);
  std::string robot_id;
  Robot* robot = RobotOfSink(sink, &robot_id);
  if (robot == nullptr) return;
  robot->session = nullptr;
  Log(api::EVENT_KIND_SESSION, robot_id, "", "session closed");
  Task* const task = SettledActiveTask(*robot);
  if (robot->session != nullptr) return;  // the robot came back while its task was planning
  // A task waiting for planning pauses for the session too, so the robot's return resumes it.
  if (task == nullptr || !task->started ||
      (task->executor->progress().state != TaskState::kRunning &&
       !task->executor->waiting_for_dependency())) {
    return;
  }
  task->paused_by_session = true;
  Apply(*task, task->executor->Pause());
}

}  // namespace semnav::reasoning
