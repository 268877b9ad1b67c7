// The gateway's coordinator behind both services: robots and their sessions, the task registry
// (core/task_registry.h), leases, the event log and idempotency, and the remote calls between
// them. One mutex guards the state; stream sinks are
// called under it and only queue. No remote call runs under it: model calls are asynchronous,
// and a task's planning call releases it (RunRemoteCall) while that task's other events wait
// for the call to end, so one slow planner stalls only its own task.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "absl/functional/function_ref.h"
#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "semnav/reasoning/v1/operator.pb.h"
#include "semnav/reasoning/v1/robot_session.pb.h"
#include "services/common/idempotency/first_answer_cache.h"
#include "services/reasoning/core/event_log.h"
#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/gateway_journal.h"
#include "services/reasoning/core/language_model.h"
#include "services/reasoning/core/lease_table.h"
#include "services/reasoning/core/model_call_policy.h"
#include "services/reasoning/core/per_task_path_planner.h"
#include "services/reasoning/core/robot_record.h"
#include "services/reasoning/core/task_decomposer.h"
#include "services/reasoning/core/task_executor.h"
#include "services/reasoning/core/task_registry.h"
#include "services/reasoning/core/telemetry_subscriptions.h"
#include "services/reasoning/core/topological_memory.h"
#include "services/reasoning/server/gateway_config.h"
#include "services/reasoning/server/lost_scan_client.h"
#include "services/reasoning/server/relocalization_client.h"
#include "services/reasoning/server/stream_sink.h"

namespace semnav::reasoning {

namespace api = ::semnav::reasoning::v1;

// Optional services of the hub; each must outlive it. Null = not configured.
struct GatewayBackends {
  ExplorationService* explorer = nullptr;    // planning's SelectExplorationGoal with task context
  LanguageModel* model = nullptr;            // model proxy: slow path and text embeddings
  const CooccurrencePrior* prior = nullptr;  // commonsense co-occurrence for exploration
  Relocalizer* relocalizer = nullptr;        // relocalization: the lost-robot loop (null = no loop)
  LostScanMatcher* lost_scan = nullptr;      // mapping's scan matcher (null = answers unrefined)
};

class GatewayHub {
 public:
  // `lexicon` and `planner` must outlive the hub. Starts the 10 Hz ticker that drives the
  // executor timeouts of wall-clock robots and slow telemetry; Shutdown() stops it (and the
  // model's pending calls).
  GatewayHub(GatewayConfig config, const Lexicon* lexicon, PathPlanner* planner,
             GatewayBackends backends = {});
  ~GatewayHub();

  absl::StatusOr<api::SubmitInstructionResponse> Submit(
      const api::SubmitInstructionRequest& request);
  absl::StatusOr<api::TaskSnapshot> GetTask(const std::string& task_id);
  absl::StatusOr<api::ListTasksResponse> ListTasks(const api::ListTasksRequest& request);
  absl::StatusOr<api::TaskSnapshot> Cancel(const api::CancelTaskRequest& request);
  absl::StatusOr<api::TaskSnapshot> Pause(const api::PauseTaskRequest& request);
  absl::StatusOr<api::TaskSnapshot> Resume(const api::ResumeTaskRequest& request);
  absl::StatusOr<api::Lease> AcquireLease(const api::AcquireLeaseRequest& request);
  absl::StatusOr<api::Lease> RenewLease(const api::RenewLeaseRequest& request);
  absl::Status ReleaseLease(const api::ReleaseLeaseRequest& request);
  absl::StatusOr<api::EmergencyStopResponse> EmergencyStop(
      const api::EmergencyStopRequest& request);
  absl::Status ClearEmergencyStop(const api::ClearEmergencyStopRequest& request);
  absl::StatusOr<api::DecomposeInstructionResponse> Decompose(
      const api::DecomposeInstructionRequest& request);
  absl::StatusOr<api::ResolveTargetResponse> ResolveTarget(
      const api::ResolveTargetRequest& request);
  // The operator's relocalization request (gateway_hub_relocalization.cc).
  absl::StatusOr<api::RelocalizeRobotResponse> RelocalizeRobot(
      const api::RelocalizeRobotRequest& request);
  // True when `fast` (ResolveTarget's answer) should go on to the slow path: allow_slow_path, no
  // fast-path target and a model proxy configured.
  bool WantsSlowPath(const api::ResolveTargetRequest& request,
                     const api::ResolveTargetResponse& fast) const;
  // The slow path for ResolveTarget: ESCA grounding, the model asked without blocking, `done`
  // called later (on the model's thread) with `fast` completed by the model's decision.
  void ResolveSlow(const api::ResolveTargetRequest& request, api::ResolveTargetResponse fast,
                   std::function<void(absl::StatusOr<api::ResolveTargetResponse>)> done)
      ABSL_LOCKS_EXCLUDED(mu_);
  // A new revision of mapping's scene graph (shared by all robots of this gateway). Tasks of
  // simulated-clock robots see it at their robot's next state, not at once.
  void OnSceneGraph(const SceneGraph& graph);
  // How a simulated-clock state brings the scene graph up to the robot's last frame: fetches
  // mapping's current graph and hands it to OnSceneGraph, within `timeout`. Unset = the graph
  // arrives only by the watch (tests without mapping).
  void SetSceneGraphSync(std::function<absl::Status(absl::Duration timeout)> sync)
      ABSL_LOCKS_EXCLUDED(mu_);

  // Streams. Watchers get the current snapshot / replayed events at once, then live ones; request
  // errors close the sink with the error.
  void WatchTask(const api::WatchTaskRequest& request, StreamSink<api::WatchTaskResponse>* sink);
  void UnwatchTask(StreamSink<api::WatchTaskResponse>* sink);
  void WatchEvents(const api::StreamEventsRequest& request,
                   StreamSink<api::StreamEventsResponse>* sink);
  void UnwatchEvents(StreamSink<api::StreamEventsResponse>* sink);
  // The retained events of a robot or task at once, with the log's newest id to stream on from.
  absl::StatusOr<api::ListEventsResponse> ListEvents(const api::ListEventsRequest& request);

  // Telemetry: fast samples on every robot state (throttled), slow samples every period.
  void WatchFastTelemetry(const api::StreamFastTelemetryRequest& request,
                          StreamSink<api::StreamFastTelemetryResponse>* sink);
  void UnwatchFastTelemetry(StreamSink<api::StreamFastTelemetryResponse>* sink);
  void WatchSlowTelemetry(const api::StreamSlowTelemetryRequest& request,
                          StreamSink<api::StreamSlowTelemetryResponse>* sink);
  void UnwatchSlowTelemetry(StreamSink<api::StreamSlowTelemetryResponse>* sink);

  // Robot sessions.
  absl::StatusOr<api::SessionAccepted> OpenSession(const api::SessionHello& hello,
                                                   StreamSink<api::ConnectResponse>* sink);
  // INVALID_ARGUMENT naming the field for a bad state (non-finite or absurd pose, velocity,
  // battery): the robot keeps its last good pose and nothing moves on it. For a simulated-clock
  // robot (docs/simulation.md, "Time") the state is one lock step: the scene graph is brought up
  // to state.mapping_revision, model answers due by the state's stamp are applied, then the
  // feedback and camera frames sent since the last state, then the pose, all at the stamp's
  // time; StepDone{state.step} follows the commands they caused.
  absl::Status OnRobotState(StreamSink<api::ConnectResponse>* sink, const api::RobotState& state);
  absl::Status OnFeedback(StreamSink<api::ConnectResponse>* sink,
                          const api::CommandFeedback& feedback);
  // A camera frame for the active task's EROI search (seed 000); dropped when the task has none
  // or its vision call is still running. INVALID_ARGUMENT naming the field for a bad frame.
  absl::Status OnCameraFrame(StreamSink<api::ConnectResponse>* sink, const api::CameraFrame& frame);
  void CloseSession(StreamSink<api::ConnectResponse>* sink);

  // Ends every open stream (server shutdown).
  void Shutdown();

 private:
  // A model answer for a simulated-clock robot, held until the robot's simulated time reaches
  // the call's issue time plus the latency the model reported.
  struct HeldAnswer {
    double due_s = 0.0;
    uint64_t order = 0;           // issue order: ties apply in the order the calls were made
    std::function<void()> apply;  // runs the answer's handler; takes mu_ itself
  };
  // The robot's state (core/robot_record.h) and what of it is the session's transport.
  struct Robot : RobotRecord {
    StreamSink<api::ConnectResponse>* session = nullptr;
    std::vector<api::ConnectRequest> step_inputs;  // feedback / camera frames since the last state
    int model_calls_in_flight = 0;  // simulated clock: calls whose answer has not come back
    std::vector<HeldAnswer> held_answers;
    api::Capabilities capabilities;  // as the hello sent them (slow telemetry)
    api::RobotState last_state;      // as sent (fast telemetry)
    api::RobotCommand last_command;
    // The relocalization loop (gateway_hub_relocalization.cc); null without a relocalizer.
    std::unique_ptr<RelocalizationLoop> localization;
    std::string localization_paused_task;  // the task the loop paused, resumed after it
  };
  using Task = TaskRecord;

  template <typename Request, typename Action>
  absl::StatusOr<api::TaskSnapshot> ControlTask(const char* method, const Request& request,
                                                Action action);
  double Now() const ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // The clock of `robot_id`'s tasks: its last state stamp for a simulated-clock robot, else Now().
  double NowFor(const std::string& robot_id) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Wraps a model call's handler for `caller`'s robot: unchanged for a wall-clock robot; for a
  // simulated-clock robot the answer is held (HeldAnswer) and applied by the state whose stamp
  // first reaches issue time + reported latency. Sets caller.reported_latency.
  template <typename Answer>
  std::function<void(Answer)> AtSimulatedArrival(ModelCaller& caller,
                                                 std::function<void(Answer)> handler)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Simulated clock: waits (bounded) for the robot's model calls to come back and applies the
  // answers due by its current time, in (due, issue) order; mu_ is released while handlers run.
  void ApplyDueAnswers(const std::string& robot_id) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Gives the executor the hub's scene graph at `now` (and notes its revision).
  std::vector<RobotCommand> GiveSceneGraph(Task& task, double now)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // One simulated-clock state: see OnRobotState.
  absl::Status OnSimulatedStep(StreamSink<api::ConnectResponse>* sink, const api::RobotState& state,
                               const RobotPose& pose) ABSL_LOCKS_EXCLUDED(mu_);
  // The pose part of a state: memory, fast telemetry and the executor.
  void HandlePose(const std::string& robot_id, Robot& robot, const api::RobotState& state,
                  const RobotPose& pose) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void HandleFeedback(Robot& robot, const api::CommandFeedback& feedback)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  absl::Status HandleCameraFrame(const std::string& robot_id, Robot& robot,
                                 const api::CameraFrame& frame) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  Robot& RobotRecord(const std::string& robot_id) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  absl::StatusOr<Task*> FindTask(const std::string& task_id) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // The task's view now, and as the API's snapshot.
  TaskView View(const Task& task) const ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  api::TaskSnapshot Snapshot(const Task& task) const ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Sends the executor's commands to the robot, bumps the revision and notifies watchers.
  void Apply(Task& task, const std::vector<RobotCommand>& commands)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void StartIfPossible(Task& task) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // The task's path planner with `strategy` (nullopt = the configured default) and its exploration
  // context.
  std::unique_ptr<PerTaskPathPlanner> PlannerFor(const std::string& task_id,
                                                 std::optional<ExplorationStrategy> strategy);
  // The task's RemoteCallRunner: called by its executor under mu_; runs `call` without mu_.
  void RunRemoteCall(const std::string& task_id, absl::FunctionRef<void()> call)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Waits (mu_ released meanwhile) until the task's executor is out of its remote call; every
  // event for an executor goes through this first. State may have changed on return.
  void AwaitExecutor(const Task& task) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // The robot's active task once its executor is free (AwaitExecutor), or null.
  Task* SettledActiveTask(Robot& robot) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Idempotency across a remote call: a retry of a request still running waits for its answer.
  // Returns the key's guard; the key is in flight until it is destroyed (under mu_).
  class RequestInFlight;
  RequestInFlight BeginRequest(const std::string& key) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // What readers see of a task: its snapshot, or the last published one while its executor is
  // inside a remote call.
  api::TaskSnapshot ReadableSnapshot(const Task& task) const ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // The executor's modality and footprint from the robot's latest hello.
  void SetMobility(Task& task, const Robot& robot) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // A new executor for `subgoals` (with the scene graph, the EROI search and the target's text
  // embedding asked for); the task's robot is not commanded yet.
  void InstallExecutor(Task& task, std::vector<Subgoal> subgoals)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // An instruction the rules found no step in: asks the model's decompose and waits for it (with
  // mu_ released, at most the call's deadline). The model's plan (a FIND completed with APPROACH
  // and VERIFY, as the rules read "find X") or, when it gives nothing usable, `rules` with the
  // reason. No task exists yet, so nothing moves while it waits.
  Decomposition DecomposeBeforeRefusing(const std::string& robot_id, const std::string& instruction,
                                        Decomposition rules) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Asks the model to decompose a complex instruction; the task runs the rule subgoals meanwhile.
  void RequestDecomposition(Task& task, Decomposition rules) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void OnDecomposition(const std::string& task_id, const Decomposition& rules,
                       absl::StatusOr<std::string> answer) ABSL_LOCKS_EXCLUDED(mu_);
  // Runs the executor's pending slow-path request on the model, without waiting for it.
  void DispatchModelRequest(Task& task) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void RequestTextEmbedding(Task& task) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Call economy: true for kAsk; logs EVENT_KIND_MODEL_BUDGET the first time the budget is spent.
  bool AllowModelCall(Task& task, CallVerdict verdict) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Model answers, on the model's threads.
  void OnModelAnswer(const std::string& task_id, uint64_t generation, const ModelRequest& request,
                     absl::StatusOr<std::string> answer) ABSL_LOCKS_EXCLUDED(mu_);
  void OnTextEmbedding(const std::string& task_id, absl::StatusOr<std::vector<float>> embedding)
      ABSL_LOCKS_EXCLUDED(mu_);
  ExplorationContext ContextFor(const std::string& task_id) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // The live-map age the task's planning calls accept (PlanningSettings::live_map_max_age_ms).
  int LiveMapMaxAgeMs(const std::string& task_id) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void OnVisionAnswer(const std::string& task_id, absl::StatusOr<std::string> answer,
                      int64_t prompt_tokens) ABSL_LOCKS_EXCLUDED(mu_);
  void OnRegionScore(const std::string& task_id, const RegionDue& region,
                     absl::StatusOr<std::string> answer) ABSL_LOCKS_EXCLUDED(mu_);
  // The strategy a task explores with: its own, else the configured default.
  ExplorationStrategy StrategyOf(const Task& task) const;
  void Tick() ABSL_LOCKS_EXCLUDED(mu_);
  // The relocalization loop (gateway_hub_relocalization.cc). TrackLocalization feeds a state
  // (pose in the robot's odometry frame), sets robot.pose to the map pose and says whether the
  // executor may use it; MayCommand keeps motion off an untrusted pose; InRobotFrame moves a
  // command's goal into the robot's odometry frame.
  bool TrackLocalization(const std::string& robot_id, Robot& robot, const api::RobotState& state,
                         const RobotPose& odom_pose) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  bool PoseTrusted(const Robot& robot) const;
  bool MayCommand(const Robot& robot, const RobotCommand& command) const;
  RobotCommand InRobotFrame(const Robot& robot, const RobotCommand& command) const;
  void OnLocalizationSession(Robot& robot) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  api::RobotLocalization LocalizationOf(const Robot& robot) const;
  void RunLocalizationActions(const std::string& robot_id, Robot& robot,
                              std::vector<RelocalizationAction> actions)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void SendLocalizationUpdate(Robot& robot) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // A service's answer to the robot's relocalization loop (`event` hands it to the loop).
  void OnLocalizationAnswer(
      const std::string& robot_id,
      const std::function<std::vector<RelocalizationAction>(RelocalizationLoop&, double now)>&
          event) ABSL_LOCKS_EXCLUDED(mu_);
  // The callback for a service call of the loop: delivers to OnLocalizationAnswer, for a
  // simulated-clock robot held until its simulated latency has passed (like a model answer).
  template <typename Answer>
  std::function<void(absl::StatusOr<Answer>)> LoopCallback(
      Robot& robot, const std::string& robot_id,
      std::vector<RelocalizationAction> (RelocalizationLoop::*deliver)(
          double, const absl::StatusOr<Answer>&)) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // The journal (gateway_hub_journal.cc): restore at construction, flush every interval and at
  // shutdown, outside mu_ for the file writes.
  void RestoreFromJournal() ABSL_LOCKS_EXCLUDED(mu_);
  void RestoreTask(const JournaledTask& saved, uint64_t next_number)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  JournaledTask JournalEntry(const Task& task) const ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void FlushJournalLoop() ABSL_LOCKS_EXCLUDED(mu_);
  void FlushJournal() ABSL_LOCKS_EXCLUDED(mu_);
  api::StreamSlowTelemetryResponse SlowSample(const std::string& robot_id)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void Log(api::EventKind kind, const std::string& robot_id, const std::string& task_id,
           std::string message) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  Robot* RobotOfSink(StreamSink<api::ConnectResponse>* sink, std::string* robot_id)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  absl::Status CheckControl(const std::string& robot_id, const std::string& lease_id)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);

  const GatewayConfig config_;
  const Lexicon* lexicon_;
  PathPlanner* planner_;
  const GatewayBackends backends_;
  const FastResolver resolver_;
  const LabelMatcher matcher_;
  const absl::Time start_;

  absl::Mutex mu_;
  std::unique_ptr<TaskDecomposer> decomposer_ ABSL_GUARDED_BY(mu_);
  std::map<std::string, Robot> robots_ ABSL_GUARDED_BY(mu_);
  TaskRegistry tasks_ ABSL_GUARDED_BY(mu_);
  // Operators watching each task (by id), until it ends.
  std::map<std::string, std::set<StreamSink<api::WatchTaskResponse>*>> task_watchers_
      ABSL_GUARDED_BY(mu_);
  LeaseTable leases_ ABSL_GUARDED_BY(mu_);
  EventLog events_ ABSL_GUARDED_BY(mu_);
  FirstAnswerCache<std::string> requests_ ABSL_GUARDED_BY(mu_);  // serialized first answers
  std::set<std::string> requests_in_flight_ ABSL_GUARDED_BY(mu_);
  std::map<StreamSink<api::StreamEventsResponse>*, std::string> event_watchers_
      ABSL_GUARDED_BY(mu_);
  TelemetrySubscriptions<StreamSink<api::StreamFastTelemetryResponse>*> fast_watchers_
      ABSL_GUARDED_BY(mu_);
  TelemetrySubscriptions<StreamSink<api::StreamSlowTelemetryResponse>*> slow_watchers_
      ABSL_GUARDED_BY(mu_);
  std::shared_ptr<const SceneGraph> scene_graph_ ABSL_GUARDED_BY(mu_) = EmptySceneGraph();
  uint64_t fast_resolutions_ ABSL_GUARDED_BY(mu_) = 0;
  uint64_t slow_resolutions_ ABSL_GUARDED_BY(mu_) = 0;
  uint64_t model_calls_ ABSL_GUARDED_BY(mu_) = 0;
  uint64_t next_model_call_ ABSL_GUARDED_BY(mu_) = 0;  // issue order of held answers
  std::function<absl::Status(absl::Duration)> scene_sync_ ABSL_GUARDED_BY(mu_);
  bool shut_down_ ABSL_GUARDED_BY(mu_) = false;
  std::thread ticker_;
  // Null without config.state_directory. journal_mu_ orders the flushes; mu_ is never held while
  // a file is written.
  absl::Mutex journal_mu_ ABSL_ACQUIRED_BEFORE(mu_);
  std::unique_ptr<GatewayJournal> journal_ ABSL_GUARDED_BY(journal_mu_);
  bool journal_dirty_ ABSL_GUARDED_BY(mu_) = false;
  std::vector<LoggedEvent> unjournaled_events_ ABSL_GUARDED_BY(mu_);
  bool journal_enabled_ = false;  // set before the threads start
  std::thread journal_flusher_;
};

class GatewayHub::RequestInFlight {
 public:
  RequestInFlight(std::set<std::string>* keys, std::string key)
      : keys_(keys), key_(std::move(key)) {
    keys_->insert(key_);
  }
  RequestInFlight(const RequestInFlight&) = delete;
  RequestInFlight& operator=(const RequestInFlight&) = delete;
  ~RequestInFlight() { keys_->erase(key_); }

 private:
  std::set<std::string>* keys_;
  std::string key_;
};

template <typename Answer>
std::function<void(Answer)> GatewayHub::AtSimulatedArrival(ModelCaller& caller,
                                                           std::function<void(Answer)> handler) {
  Robot& robot = RobotRecord(caller.robot_id);
  if (!robot.simulated_clock) return handler;
  ++robot.model_calls_in_flight;
  caller.reported_latency = std::make_shared<absl::Duration>(absl::ZeroDuration());
  return [this, robot_id = caller.robot_id, issued_s = robot.sim_now_s, order = next_model_call_++,
          latency = caller.reported_latency, handler = std::move(handler)](Answer answer) {
    absl::MutexLock lock(&mu_);
    Robot& arrived = RobotRecord(robot_id);
    --arrived.model_calls_in_flight;
    arrived.held_answers.push_back(
        {issued_s + absl::ToDoubleSeconds(*latency), order,
         [handler, answer = std::move(answer)]() mutable { handler(std::move(answer)); }});
  };
}

}  // namespace semnav::reasoning
