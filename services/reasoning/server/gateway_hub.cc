// GatewayHub: construction, the ticker, snapshots and the task lifecycle.
#include "services/reasoning/server/gateway_hub.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/strings/strip.h"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"
#include "services/reasoning/core/correction.h"
#include "services/reasoning/server/hub_internal.h"
#include "services/reasoning/server/proto_convert.h"
#include "services/reasoning/server/request_checks.h"

namespace semnav::reasoning {

using namespace hub_internal;

GatewayHub::GatewayHub(GatewayConfig config, const Lexicon* lexicon, PathPlanner* planner, GatewayBackends backends)
    : config_(config),
      lexicon_(lexicon),
      planner_(planner),
      backends_(backends),
      resolver_(lexicon, config.fast_path),
      matcher_(lexicon, config.fast_path.unknown_colour_factor),
      start_(absl::Now()),
      events_(static_cast<std::size_t>(config.retained_events)),
      requests_(static_cast<std::size_t>(config.idempotency_entries)) {
  absl::StatusOr<TextSegmenter> segmenter = TextSegmenter::Create();
  if (segmenter.ok()) {
    decomposer_ = std::make_unique<TaskDecomposer>(InstructionParser(lexicon, *std::move(segmenter)), config.decomposer);
  }
  journal_enabled_ = !config_.state_directory.empty();
  if (journal_enabled_) {
    RestoreFromJournal();
    journal_flusher_ = std::thread([this] { FlushJournalLoop(); });
  }
  ticker_ = std::thread([this] { Tick(); });
}

GatewayHub::~GatewayHub() {
  Shutdown();
  if (ticker_.joinable()) ticker_.join();
  if (journal_flusher_.joinable()) journal_flusher_.join();
}

// 10 Hz: timeouts of running tasks even when a robot stops reporting, and slow telemetry.
void GatewayHub::Tick() {
  absl::MutexLock lock(&mu_);
  while (!shut_down_) {
    mu_.AwaitWithTimeout(absl::Condition(&shut_down_), absl::Milliseconds(100));
    if (shut_down_) break;
    for (auto& [robot_id, robot] : robots_) {
      if (robot.simulated_clock || !PoseTrusted(robot)) continue;  // its states are its clock / relocalizing
      auto task = tasks_.find(robot.active_task);
      if (task != tasks_.end() && task->second.started) Apply(task->second, task->second.executor->OnPose(Now(), robot.pose));
    }
    const absl::Time now = absl::Now();
    for (auto& [sink, subscription] : slow_watchers_) {
      if (now - subscription.last_sent < subscription.interval) continue;
      subscription.last_sent = now;
      sink->Send(SlowSample(subscription.robot_id));
    }
  }
}

std::string GatewayHub::StrategyOf(const Task& task) const {
  return task.planner->strategy().empty() ? config_.planning.exploration_strategy : task.planner->strategy();
}

double GatewayHub::Now() const { return absl::ToDoubleSeconds(absl::Now() - start_); }

GatewayHub::Robot& GatewayHub::RobotRecord(const std::string& robot_id) {
  Robot& robot = robots_[robot_id];
  if (robot.memory == nullptr) robot.memory = std::make_unique<TopologicalMemory>(&matcher_, config_.memory);
  return robot;
}

absl::StatusOr<GatewayHub::Task*> GatewayHub::FindTask(const std::string& task_id) {
  auto it = tasks_.find(task_id);
  if (it == tasks_.end()) {
    return FieldError(absl::StatusCode::kNotFound, "task_id",
                      absl::StrCat("no task '", Preview(task_id), "'"), "NOT_FOUND");
  }
  return &it->second;
}

absl::Status GatewayHub::CheckControl(const std::string& robot_id, const std::string& lease_id) {
  absl::Status status = leases_.CheckControl(robot_id, lease_id, absl::Now());
  if (status.ok()) return status;
  return FieldError(absl::StatusCode::kFailedPrecondition, "lease_id", status.message(), "LEASE_HELD");
}

void GatewayHub::Log(api::EventKind kind, const std::string& robot_id, const std::string& task_id,
                     std::string message) {
  const LoggedEvent& event = events_.Append(kind, robot_id, task_id, std::move(message), absl::Now());
  if (journal_enabled_) unjournaled_events_.push_back(event);
  api::StreamEventsResponse response;
  *response.mutable_event() = ToProto(event);
  for (auto& [sink, filter] : event_watchers_) {
    if (filter.empty() || filter == robot_id) sink->Send(response);
  }
}

api::TaskSnapshot GatewayHub::Snapshot(const Task& task) const {
  api::TaskSnapshot out;
  const TaskProgress& progress = task.executor->progress();
  out.set_task_id(task.task_id);
  out.set_robot_id(task.robot_id);
  out.set_instruction(task.instruction);
  out.set_status(!task.started && progress.state == TaskState::kRunning ? api::TASK_STATUS_PENDING
                                                                          : ToProto(progress.state));
  out.set_revision(task.revision);
  for (const Subgoal& goal : task.executor->subgoals()) *out.add_subgoals() = ToProto(goal);
  out.set_current_subgoal(progress.subgoal_index);
  out.set_phase(progress.phase);
  out.set_reason(progress.reason);
  if (progress.target.has_value()) {
    api::ResolvedTarget* target = out.mutable_target();
    target->set_object_id(progress.target->object_id);
    target->mutable_position()->set_x(progress.target->position.x());
    target->mutable_position()->set_y(progress.target->position.y());
    target->mutable_position()->set_z(progress.target->position.z());
    target->set_confidence(progress.target->confidence);
    target->set_path(progress.target->path == "fast" ? api::RESOLUTION_PATH_FAST : api::RESOLUTION_PATH_SLOW);
  }
  for (const Eigen::Vector3d& point : progress.path) {
    common::v1::Vector3* p = out.add_path();
    p->set_x(point.x());
    p->set_y(point.y());
    p->set_z(point.z());
  }
  const std::size_t count = task.executor->subgoals().size();
  out.set_progress(count == 0 ? 1.0 : std::min(1.0, static_cast<double>(progress.subgoal_index) / count));
  out.set_decomposition_source(task.source);
  out.set_replans(progress.replans);
  out.set_explore_goals(progress.explore_goals);
  out.set_model_requests(progress.model_requests);
  out.set_model_calls(task.model_calls);
  if (backends_.explorer != nullptr) out.set_exploration_strategy(StrategyOf(task));
  if (task.search_area.has_value()) *out.mutable_search_area() = ToProto(*task.search_area);
  *out.mutable_created_at() = ToTimestamp(task.created);
  *out.mutable_updated_at() = ToTimestamp(task.updated);
  return out;
}

void GatewayHub::Apply(Task& task, const std::vector<RobotCommand>& commands) {
  Robot& robot = RobotRecord(task.robot_id);
  for (const RobotCommand& command : commands) {
    if (robot.session == nullptr) break;
    if (!MayCommand(robot, command)) continue;  // no motion on an untrusted pose
    api::ConnectResponse response;
    robot.last_session_command = robot.next_command_id++;
    robot.last_executor_command = command.id;
    *response.mutable_command() = ToProto(InRobotFrame(robot, command), robot.last_session_command, task.task_id);
    robot.last_command = response.command();
    robot.session->Send(response);
  }
  DispatchModelRequest(task);
  api::TaskSnapshot snapshot = Snapshot(task);
  snapshot.clear_revision();
  snapshot.clear_updated_at();
  std::string fingerprint = snapshot.SerializeAsString();
  if (fingerprint == task.fingerprint && commands.empty()) return;
  const api::TaskSnapshot before = std::move(task.published);
  task.fingerprint = std::move(fingerprint);
  ++task.revision;
  journal_dirty_ = true;
  task.updated = absl::Now();
  api::WatchTaskResponse response;
  *response.mutable_task() = Snapshot(task);
  const api::TaskSnapshot& now = response.task();
  if (!before.has_target() && now.has_target()) {
    ++(now.target().path() == api::RESOLUTION_PATH_FAST ? fast_resolutions_ : slow_resolutions_);
    Log(api::EVENT_KIND_GOAL_RESOLVED, task.robot_id, task.task_id,
        absl::StrCat("object ", now.target().object_id(), " by the ", api::ResolutionPath_Name(now.target().path())));
  }
  // A dependency pause is logged even when the task was already PAUSED (an operator's resume
  // that found planning gone) or had no snapshot yet (it paused as it started).
  const bool dependency_lost =
      now.phase() == "dependency_unavailable" && before.phase() != "dependency_unavailable";
  if ((before.status() != now.status() && before.status() != api::TASK_STATUS_UNSPECIFIED) ||
      dependency_lost) {
    Log(api::EVENT_KIND_TASK_STATUS, task.robot_id, task.task_id,
        absl::StrCat(api::TaskStatus_Name(now.status()), ": ", now.reason()));
  } else if (before.current_subgoal() != now.current_subgoal()) {
    Log(api::EVENT_KIND_SUBGOAL, task.robot_id, task.task_id, absl::StrCat("subgoal ", now.current_subgoal()));
  }
  task.published = now;
  for (StreamSink<api::WatchTaskResponse>* watcher : task.watchers) watcher->Send(response);
  if (task.executor->finished()) {
    for (StreamSink<api::WatchTaskResponse>* watcher : task.watchers) watcher->Close(grpc::Status::OK);
    task.watchers.clear();
    if (robot.active_task == task.task_id) robot.active_task.clear();
  }
}

std::unique_ptr<TaskPlanner> GatewayHub::PlannerFor(const std::string& task_id, const std::string& strategy) {
  return std::make_unique<TaskPlanner>(planner_, backends_.explorer, strategy,
                                       [this, task_id]() ABSL_NO_THREAD_SAFETY_ANALYSIS {
                                         // Called by the executor, under mu_.
                                         return ContextFor(task_id);
                                       });
}

void GatewayHub::StartIfPossible(Task& task) {
  Robot& robot = RobotRecord(task.robot_id);
  if (task.started || robot.session == nullptr) {
    Apply(task, {});
    return;
  }
  task.started = true;
  SetMobility(task, robot);
  Apply(task, task.executor->Start(NowFor(task.robot_id), robot.pose));
}

void GatewayHub::InstallExecutor(Task& task, std::vector<Subgoal> subgoals) {
  ExecutorConfig executor = config_.executor;
  executor.model_available = backends_.model != nullptr;
  ++task.executor_generation;
  task.executor = std::make_unique<TaskExecutor>(task.instruction, std::move(subgoals), &resolver_,
                                                 task.planner.get(), RobotRecord(task.robot_id).memory.get(), executor);
  GiveSceneGraph(task, NowFor(task.robot_id));
  const TargetSpec* target = PrimaryTarget(task.executor->subgoals());
  task.eroi.reset();
  // The operator's search area is the EROI volume when it is given (the configured one's edge,
  // z layers and drawing kept); otherwise the configured volume, if any.
  std::optional<EroiSearchConfig> eroi = config_.eroi;
  if (task.search_area.has_value()) {
    EroiSearchConfig fitted = eroi.value_or(DefaultEroiSearch());
    fitted.grid = GridOverArea(fitted.grid, task.search_area->min, task.search_area->max);
    eroi = fitted;
  }
  if (StrategyOf(task) == "EROI_UTILITY" && eroi.has_value() && target != nullptr) {
    absl::StatusOr<EroiSearch> search =
        EroiSearch::Create(target->text.empty() ? target->name : target->text, *eroi);
    if (search.ok()) task.eroi = std::make_unique<EroiSearch>(*std::move(search));
  }
  RequestTextEmbedding(task);
}

std::vector<RobotCommand> GatewayHub::GiveSceneGraph(Task& task, double now) {
  task.graph_revision = scene_graph_.revision;
  return task.executor->OnSceneGraph(now, scene_graph_);
}

void GatewayHub::SetMobility(Task& task, const Robot& robot) {
  const api::Capabilities& caps = robot.capabilities;
  const bool fly_roll = std::find(caps.modes().begin(), caps.modes().end(), api::LOCOMOTION_MODE_FLY_ROLL) !=
                        caps.modes().end();
  task.executor->SetMobility(fly_roll, caps.footprint_radius_m());
}

absl::StatusOr<api::SubmitInstructionResponse> GatewayHub::Submit(const api::SubmitInstructionRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.request_id(), "request_id"); !s.ok()) return s;
  const std::string key = absl::StrCat("Submit:", request.request_id());
  if (auto cached = Cached<api::SubmitInstructionResponse>(requests_, key)) return *cached;
  if (absl::Status s = Required(request.robot_id(), "robot_id"); !s.ok()) return s;
  if (absl::Status s = Required(request.instruction(), "instruction"); !s.ok()) return s;
  if (!api::ExplorationStrategy_IsValid(request.exploration_strategy())) {
    return FieldError(absl::StatusCode::kInvalidArgument, "exploration_strategy",
                      absl::StrCat("unknown value ", request.exploration_strategy()));
  }
  std::optional<SearchArea> search_area;
  if (request.has_search_area()) {
    absl::StatusOr<SearchArea> area = FromProto(request.search_area());
    if (!area.ok()) return area.status();
    search_area = *area;
  }
  if (decomposer_ == nullptr) return absl::InternalError("ICU word break iterator unavailable");
  Robot& robot = RobotRecord(request.robot_id());
  if (robot.emergency_stop) {
    return FieldError(absl::StatusCode::kFailedPrecondition, "robot_id", "emergency stop active", "EMERGENCY_STOP");
  }
  if (absl::Status s = CheckControl(request.robot_id(), request.lease_id()); !s.ok()) return s;

  api::SubmitInstructionResponse response;
  auto active = tasks_.find(robot.active_task);
  if (request.allow_correction() && active != tasks_.end() && !active->second.executor->finished()) {
    Task& task = active->second;
    const TargetSpec* target = PrimaryTarget(task.executor->subgoals());
    std::optional<Correction> correction =
        target != nullptr ? ReadCorrection(decomposer_->parser().Parse(request.instruction()), *target) : std::nullopt;
    if (correction.has_value()) {
      Log(api::EVENT_KIND_CORRECTION, task.robot_id, task.task_id, request.instruction());
      Apply(task, task.executor->Retarget(NowFor(task.robot_id), correction->target, correction->exclude_current));
      response.set_task_id(task.task_id);
      response.set_correction_applied(true);
      *response.mutable_task() = Snapshot(task);
      requests_.Put(key, response.SerializeAsString());
      return response;
    }
  }
  Decomposition decomposition = decomposer_->Decompose(request.instruction());
  if (decomposition.subgoals.empty()) {
    return FieldError(absl::StatusCode::kInvalidArgument, "instruction", "no actionable step understood");
  }
  if (active != tasks_.end() && !active->second.executor->finished()) {
    Task& previous = active->second;
    Apply(previous, previous.executor->Cancel("replaced by a new instruction"));
  }
  const std::string task_id = absl::StrCat("task-", next_task_++);
  Task& task = tasks_[task_id];
  task.task_id = task_id;
  task.calls = ModelCallPolicy(config_.model_proxy.calls);
  task.robot_id = request.robot_id();
  task.instruction = request.instruction();
  task.source = decomposition.source;
  task.search_area = search_area;
  task.created = task.updated = absl::Now();
  // "" = the configured default; otherwise planning's name ("EROI_UTILITY").
  const std::string strategy =
      request.exploration_strategy() == api::EXPLORATION_STRATEGY_UNSPECIFIED
          ? ""
          : std::string(absl::StripPrefix(api::ExplorationStrategy_Name(request.exploration_strategy()),
                                          "EXPLORATION_STRATEGY_"));
  task.planner = PlannerFor(task_id, strategy);
  InstallExecutor(task, decomposition.subgoals);
  robot.active_task = task_id;
  Log(api::EVENT_KIND_TASK_CREATED, task.robot_id, task_id, request.instruction());
  if (decomposition.complex && backends_.model != nullptr) RequestDecomposition(task, std::move(decomposition));
  StartIfPossible(task);
  response.set_task_id(task_id);
  *response.mutable_task() = Snapshot(task);
  requests_.Put(key, response.SerializeAsString());
  return response;
}

absl::StatusOr<api::TaskSnapshot> GatewayHub::GetTask(const std::string& task_id) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = CheckLength(task_id, "task_id", kMaxIdBytes); !s.ok()) return s;
  absl::StatusOr<Task*> task = FindTask(task_id);
  if (!task.ok()) return task.status();
  return Snapshot(**task);
}

absl::StatusOr<api::ListTasksResponse> GatewayHub::ListTasks(const api::ListTasksRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  std::vector<const Task*> selected;
  for (const auto& [id, task] : tasks_) {
    if (!request.robot_id().empty() && task.robot_id != request.robot_id()) continue;
    if (request.unfinished_only() && task.executor->finished()) continue;
    selected.push_back(&task);
  }
  // Ids are "task-<n>" with n counting up, so (length, id) is submission order.
  std::sort(selected.begin(), selected.end(), [](const Task* a, const Task* b) {
    return std::make_pair(a->task_id.size(), a->task_id) < std::make_pair(b->task_id.size(), b->task_id);
  });
  api::ListTasksResponse response;
  for (const Task* task : selected) *response.add_tasks() = Snapshot(*task);
  return response;
}

// Cancel, pause and resume share validation, the lease check and idempotency.
template <typename Request, typename Action>
absl::StatusOr<api::TaskSnapshot> GatewayHub::ControlTask(const char* method, const Request& request, Action action) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.request_id(), "request_id"); !s.ok()) return s;
  const std::string key = absl::StrCat(method, ":", request.request_id());
  if (auto cached = Cached<api::TaskSnapshot>(requests_, key)) return *cached;
  absl::StatusOr<Task*> found = FindTask(request.task_id());
  if (!found.ok()) return found.status();
  Task& task = **found;
  if (task.executor->finished()) {
    // A retry of the call that ended the task was answered from the cache above.
    return FieldError(absl::StatusCode::kFailedPrecondition, "task_id",
                      absl::StrCat("task ", task.task_id, " already finished (",
                                   api::TaskStatus_Name(Snapshot(task).status()), ")"),
                      "TASK_FINISHED");
  }
  if (absl::Status s = CheckControl(task.robot_id, request.lease_id()); !s.ok()) return s;
  action(task);
  api::TaskSnapshot snapshot = Snapshot(task);
  requests_.Put(key, snapshot.SerializeAsString());
  return snapshot;
}

absl::StatusOr<api::TaskSnapshot> GatewayHub::Cancel(const api::CancelTaskRequest& request) {
  return ControlTask("Cancel", request, [&](Task& task) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_) {
    Apply(task, task.executor->Cancel(request.reason().empty() ? "cancelled by the operator" : request.reason()));
  });
}

absl::StatusOr<api::TaskSnapshot> GatewayHub::Pause(const api::PauseTaskRequest& request) {
  return ControlTask("Pause", request,
                     [&](Task& task) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_) { Apply(task, task.executor->Pause()); });
}

absl::StatusOr<api::TaskSnapshot> GatewayHub::Resume(const api::ResumeTaskRequest& request) {
  return ControlTask("Resume", request, [&](Task& task) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_) {
    if (RobotRecord(task.robot_id).session == nullptr) {
      task.paused_by_session = true;  // resumes when the robot reconnects
    } else {
      Apply(task, task.executor->Resume(NowFor(task.robot_id)));
    }
  });
}

absl::StatusOr<api::DecomposeInstructionResponse> GatewayHub::Decompose(
    const api::DecomposeInstructionRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.instruction(), "instruction"); !s.ok()) return s;
  if (decomposer_ == nullptr) return absl::InternalError("ICU word break iterator unavailable");
  const Decomposition decomposition = decomposer_->Decompose(request.instruction());
  api::DecomposeInstructionResponse response;
  for (const Subgoal& goal : decomposition.subgoals) *response.add_subgoals() = ToProto(goal);
  response.set_source(decomposition.source);
  response.set_complex(decomposition.complex);
  return response;
}

void GatewayHub::OnSceneGraph(const SceneGraph& graph) {
  absl::MutexLock lock(&mu_);
  scene_graph_ = graph;
  for (auto& [robot_id, robot] : robots_) {
    if (robot.simulated_clock) continue;  // its task gets the graph with its next state
    auto task = tasks_.find(robot.active_task);
    if (task == tasks_.end()) continue;
    // Not-yet-started tasks keep the graph too, so they start with it.
    std::vector<RobotCommand> commands = GiveSceneGraph(task->second, Now());
    if (task->second.started) Apply(task->second, commands);
  }
}

absl::StatusOr<api::ResolveTargetResponse> GatewayHub::ResolveTarget(const api::ResolveTargetRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.robot_id(), "robot_id"); !s.ok()) return s;
  TargetSpec target;
  if (request.has_target()) {
    target = FromProto(request.target());
    if (target.empty()) return FieldError(absl::StatusCode::kInvalidArgument, "target.name", "is required");
  } else {
    if (absl::Status s = Required(request.text(), "text"); !s.ok()) return s;
    if (decomposer_ == nullptr) return absl::InternalError("ICU word break iterator unavailable");
    const Decomposition decomposition = decomposer_->Decompose(request.text());
    const TargetSpec* primary = PrimaryTarget(decomposition.subgoals);
    if (primary == nullptr) return FieldError(absl::StatusCode::kInvalidArgument, "text", "no target understood");
    target = *primary;
  }
  api::ResolveTargetResponse response;
  *response.mutable_understood() = ToProto(target);
  const FastResolution resolution = resolver_.Resolve(target, scene_graph_, {}, {});
  if (resolution.best.has_value()) {
    const SceneObject* object = scene_graph_.FindObject(resolution.best->object_id);
    api::ScoredCandidate* candidate = response.mutable_best_candidate();
    candidate->set_object_id(object->id);
    candidate->set_label(object->label);
    candidate->mutable_position()->set_x(object->position.x());
    candidate->mutable_position()->set_y(object->position.y());
    candidate->mutable_position()->set_z(object->position.z());
    api::FusedScore* score = candidate->mutable_score();
    score->set_label(resolution.best->label);
    score->set_embedding(resolution.best->embedding);
    score->set_detector(resolution.best->detector);
    score->set_spatial(resolution.best->spatial);
    score->set_fused(resolution.best->fused);
    if (resolution.accepted) {
      api::ResolvedTarget* resolved = response.mutable_target();
      resolved->set_object_id(object->id);
      *resolved->mutable_position() = candidate->position();
      resolved->set_confidence(resolution.best->fused);
      resolved->set_path(api::RESOLUTION_PATH_FAST);
      resolved->set_label(object->label);
    }
  }
  if (request.allow_slow_path() && !resolution.accepted && backends_.model == nullptr) {
    response.set_explanation("slow path not run: no model proxy is configured in this gateway");
  }
  return response;
}

void GatewayHub::Shutdown() {
  {
    absl::MutexLock lock(&mu_);
    if (!shut_down_) {
      if (journal_enabled_) {
        // A stopped gateway ends its tasks (the robots get a stop) so a fresh start never drives
        // an old one; only a crash leaves tasks to resume.
        for (auto& [id, task] : tasks_) {
          if (!task.executor->finished()) Apply(task, task.executor->Cancel("gateway stopped"));
        }
      }
      shut_down_ = true;
      const grpc::Status status(grpc::StatusCode::UNAVAILABLE, "gateway shutting down");
      for (auto& [id, task] : tasks_) {
        for (StreamSink<api::WatchTaskResponse>* watcher : task.watchers) watcher->Close(status);
        task.watchers.clear();
      }
      for (auto& [sink, filter] : event_watchers_) sink->Close(status);
      event_watchers_.clear();
      for (auto& [sink, subscription] : fast_watchers_) sink->Close(status);
      fast_watchers_.clear();
      for (auto& [sink, subscription] : slow_watchers_) sink->Close(status);
      slow_watchers_.clear();
      for (auto& [id, robot] : robots_) {
        if (robot.session != nullptr) robot.session->Close(status);
      }
    }
  }
  if (journal_enabled_) FlushJournal();
  // Outside the lock: an answer being delivered waits for mu_ (and then finds the hub shut down).
  if (backends_.model != nullptr) backends_.model->Stop();
}

}  // namespace semnav::reasoning
