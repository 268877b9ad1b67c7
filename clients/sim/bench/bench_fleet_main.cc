// semnav-bench-fleet: N simulated robots against ONE stack (mapping, planning, gateway) in real
// time. Each robot holds a gateway session (state at 5 Hz, command feedback), streams depth
// frames with detections to mapping at 1 Hz and runs its own search task, submitted through
// OperatorService; an operator thread polls every robot's task with GetTask. Reports command
// latency, operator RPC latency, errors and the services' RSS over the run (docs/performance.md).
#include <sys/types.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_split.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/sim_robot.h"
#include "clients/sim/loop/command_executor.h"
#include "clients/sim/loop/episode_spec.h"
#include "clients/sim/loop/frame_encoder.h"
#include "clients/sim/loop/frame_stream.h"
#include "clients/sim/loop/instruction.h"
#include "clients/sim/loop/local_planner.h"
#include "clients/sim/loop/robot_messages.h"
#include "clients/sim/loop/robot_session.h"
#include "clients/sim/loop/sim_stack.h"
#include "clients/sim/worlds/indoor_generator.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "services/common/cli/executable_dir.h"
#include "services/common/cli/flags.h"

namespace {

namespace loop = semnav::sim::loop;
namespace sim = semnav::sim;
namespace api = semnav::reasoning::v1;

const std::vector<semnav::FlagSpec> kFlags = {
    {"robots", "N", "simulated robots against the one stack (default 5)"},
    {"sweep", "LIST",
     "comma-separated robot counts, one fresh stack and run each (e.g. 1,5,10,25,50)"},
    {"duration-s", "S", "wall seconds each run lasts (default 60)"},
    {"json", "FILE", "also write the results as JSON"},
    {"world-seed", "N", "seed of the generated home all robots share (default 7)"},
    {"robot-threads", "N", "threads stepping the robots (default 8, at most one per robot)"},
    {"operator-poll-ms", "MS",
     "period of the operator's GetTask round over all tasks (default 500)"},
    {"help", "", "this text"},
};

constexpr absl::Duration kStep = absl::Milliseconds(200);  // 5 Hz state, real-time stepping
constexpr double kStepS = 0.2;
constexpr int kStepsPerFrame = 5;  // 1 Hz frames to mapping
// Warm-up: RSS growth is counted from the later of this share of the run and the time the live
// map settled (its explored area grew by less than kSettledGrowth over the next kSettleWindowS):
// until then mapping's memory follows the map of a home the robots are still discovering, which
// is bounded by the home, not a leak.
constexpr double kWarmUpShare = 0.2;
constexpr double kSettledGrowth = 0.01;
constexpr double kSettleWindowS = 30.0;
constexpr absl::Duration kRssPeriod = absl::Milliseconds(500);
constexpr int kMapEveryRss = 10;  // the live map's size every 10 RSS samples (5 s)
constexpr absl::Duration kRpcDeadline = absl::Seconds(10);

// The targets for "a fleet of N meets them".
constexpr double kCommandP99TargetMs = 50.0;
constexpr double kOperatorP99TargetMs = 10.0;
constexpr double kRssGrowthTargetPct = 5.0;

// A task's final STOP must not end the robot's life: it only halts (the emergency form), which
// keeps it ready for its next task (as semnav-dashboard-sim-robot does).
api::RobotCommand KeepAlive(api::RobotCommand command) {
  if (command.has_stop()) command.mutable_stop()->set_emergency(true);
  return command;
}

bool Terminal(api::TaskStatus status) {
  return status == api::TASK_STATUS_SUCCEEDED || status == api::TASK_STATUS_FAILED ||
         status == api::TASK_STATUS_CANCELLED;
}

// Whether the robot's report that ends this command makes the gateway's next command due at
// once: a navigate's GOAL_REACHED, BLOCKED or FAILED (the executor answers each with a command,
// VERIFY's with a hold). Not a rotate or hold: those are intentional waits that the gateway ends
// by its own clock, so their successor is due at the gateway's deadline and may be on its way
// before the robot reports.
bool AnsweredOnReport(const api::RobotCommand& command) { return command.has_navigate(); }

bool EndsCommand(api::FeedbackKind kind) {
  return kind == api::FEEDBACK_KIND_GOAL_REACHED || kind == api::FEEDBACK_KIND_BLOCKED ||
         kind == api::FEEDBACK_KIND_FAILED;
}

double Ms(absl::Duration d) { return absl::ToDoubleMilliseconds(d); }

// Nearest-rank percentile; NaN for no samples.
double Percentile(std::vector<double> samples, double p) {
  if (samples.empty()) return std::nan("");
  std::sort(samples.begin(), samples.end());
  const size_t rank = static_cast<size_t>(std::ceil(p / 100.0 * samples.size()));
  return samples[std::clamp<size_t>(rank, 1, samples.size()) - 1];
}

// VmRSS of a process in KiB; nullopt when it is gone.
std::optional<long> RssKb(pid_t pid) {
  std::ifstream status(absl::StrCat("/proc/", pid, "/status"));
  std::string line;
  while (std::getline(status, line)) {
    long kb = 0;
    if (line.rfind("VmRSS:", 0) == 0 &&
        absl::SimpleAtoi(absl::StripAsciiWhitespace(absl::StripSuffix(line.substr(6), "kB")),
                         &kb)) {
      return kb;
    }
  }
  return std::nullopt;
}

// One of the slowest report -> next command samples: what the robot reported the end of, and
// what came next (the commands' reasons), so a slow p99 can be read.
struct SlowCommand {
  double ms = 0.0;
  std::string reported;
  std::string next;
};
constexpr size_t kSlowestKept = 5;

// Everything the threads record, under one lock: the run's figures.
class Recorder {
 public:
  void Instruction(absl::Duration d) { Add(instruction_ms_, Ms(d)); }
  // A report -> next command sample, with both commands' reasons for the slowest few.
  void Feedback(absl::Duration d, const std::string& reported, const std::string& next) {
    absl::MutexLock lock(&mu_);
    feedback_ms_.push_back(Ms(d));
    slowest_.push_back({Ms(d), reported, next});
    std::sort(slowest_.begin(), slowest_.end(),
              [](const SlowCommand& a, const SlowCommand& b) { return a.ms > b.ms; });
    if (slowest_.size() > kSlowestKept) slowest_.pop_back();
  }
  void Operator(absl::Duration d) { Add(operator_ms_, Ms(d)); }
  void Error(const std::string& what) {
    absl::MutexLock lock(&mu_);
    ++errors_;
    if (error_samples_.size() < 5) error_samples_.push_back(what);
  }
  void LateStep() {
    absl::MutexLock lock(&mu_);
    ++late_steps_;
  }
  void TaskSubmitted() {
    absl::MutexLock lock(&mu_);
    ++tasks_submitted_;
  }
  void TaskEnded(api::TaskStatus status) {
    absl::MutexLock lock(&mu_);
    ++tasks_ended_[api::TaskStatus_Name(status)];
  }

  std::vector<double> instruction_ms() { return Copy(instruction_ms_); }
  std::vector<double> feedback_ms() { return Copy(feedback_ms_); }
  std::vector<SlowCommand> slowest() {
    absl::MutexLock lock(&mu_);
    return slowest_;
  }
  std::vector<double> operator_ms() { return Copy(operator_ms_); }
  int errors() {
    absl::MutexLock lock(&mu_);
    return errors_;
  }
  std::vector<std::string> error_samples() {
    absl::MutexLock lock(&mu_);
    return error_samples_;
  }
  int late_steps() {
    absl::MutexLock lock(&mu_);
    return late_steps_;
  }
  int tasks_submitted() {
    absl::MutexLock lock(&mu_);
    return tasks_submitted_;
  }
  std::map<std::string, int> tasks_ended() {
    absl::MutexLock lock(&mu_);
    return tasks_ended_;
  }

 private:
  void Add(std::vector<double>& to, double value) {
    absl::MutexLock lock(&mu_);
    to.push_back(value);
  }
  std::vector<double> Copy(const std::vector<double>& from) {
    absl::MutexLock lock(&mu_);
    return from;
  }

  absl::Mutex mu_;
  std::vector<double> instruction_ms_ ABSL_GUARDED_BY(mu_);
  std::vector<double> feedback_ms_ ABSL_GUARDED_BY(mu_);
  std::vector<SlowCommand> slowest_ ABSL_GUARDED_BY(mu_);
  std::vector<double> operator_ms_ ABSL_GUARDED_BY(mu_);
  int errors_ ABSL_GUARDED_BY(mu_) = 0;
  std::vector<std::string> error_samples_ ABSL_GUARDED_BY(mu_);
  int late_steps_ ABSL_GUARDED_BY(mu_) = 0;
  int tasks_submitted_ ABSL_GUARDED_BY(mu_) = 0;
  std::map<std::string, int> tasks_ended_ ABSL_GUARDED_BY(mu_);
};

// The one home all robots share (one live map, consistent for all of them) and its labels.
struct SharedWorld {
  sim::World world;
  std::unique_ptr<sim::Scene> scene;
  std::vector<std::string> labels;  // distinct object labels, the search targets
};

struct FleetRobot {
  std::string id;
  int index = 0;
  sim::RobotConfig config;
  std::unique_ptr<sim::SimRobot> sim;
  std::unique_ptr<loop::CommandExecutor> executor;
  std::unique_ptr<loop::RobotSession> session;
  std::unique_ptr<loop::FrameStream> frames;
  int step = 0;
  absl::Time next_step;
  bool failed = false;
  int tasks = 0;
  absl::Time submitted_at;
  bool first_command_seen = true;
  // The latest command and, once the robot reported its end, when it did so.
  std::optional<api::RobotCommand> current;
  std::optional<absl::Time> report_sent_at;
  // Shared with the operator thread.
  absl::Mutex task_mu;
  std::string task_id ABSL_GUARDED_BY(task_mu);
  bool task_over ABSL_GUARDED_BY(task_mu) = false;
};

class Fleet {
 public:
  Fleet(const SharedWorld& shared, const loop::Endpoints& endpoints, Recorder& recorder)
      : shared_(shared),
        endpoints_(endpoints),
        recorder_(recorder),
        operator_(api::OperatorService::NewStub(endpoints.gateway)) {}

  // Connects robot `index`: session, frame stream, first state and frame, first task.
  absl::Status AddRobot(int index, int fleet_size) {
    auto robot = std::make_unique<FleetRobot>();
    robot->id = absl::StrCat("fleet-", index);
    robot->index = index;
    sim::StartPose start = shared_.world.starts[index % shared_.world.starts.size()];
    start.yaw += 2.399963 * index;  // golden angle: robots on one start look different ways
    robot->config = sim::RobotConfig::ForModality(start.modality);
    if (start.modality == sim::Modality::kGround) robot->config.camera_pitch = 0.35;
    robot->sim =
        std::make_unique<sim::SimRobot>(shared_.world, *shared_.scene, start, robot->config,
                                        loop::LoopSensorConfig(), 1000 + index);
    robot->executor = std::make_unique<loop::CommandExecutor>(
        *robot->sim, loop::LiveMapPlanner(endpoints_.planning, robot->config.radius));
    absl::StatusOr<std::unique_ptr<loop::RobotSession>> session = loop::RobotSession::Open(
        endpoints_.gateway, loop::Hello(robot->id, start.modality, robot->config));
    if (!session.ok()) return session.status();
    robot->session = std::move(*session);
    robot->frames = std::make_unique<loop::FrameStream>(endpoints_.mapping);
    // The gateway must know where the robot is and what it sees before it plans.
    if (absl::Status s = robot->session->Send(loop::StateMessage(*robot->sim, robot->id)); !s.ok())
      return s;
    if (absl::Status s = SendFrame(*robot); !s.ok()) return s;
    if (absl::Status s = SubmitTask(*robot); !s.ok()) return s;
    // Spread over one step so that the fleet's messages do not arrive in bursts.
    robot->step = index;
    robot->next_step = absl::Now() + kStep * index / std::max(fleet_size, 1);
    robots_.push_back(std::move(robot));
    return absl::OkStatus();
  }

  void Run(absl::Time end, int threads, absl::Duration operator_period) {
    threads = std::clamp<int>(threads, 1, static_cast<int>(robots_.size()));
    std::vector<std::thread> workers;
    for (int w = 0; w < threads; ++w) {
      workers.emplace_back([this, w, threads, end] { StepRobots(w, threads, end); });
    }
    std::thread operator_thread([this, end, operator_period] { PollTasks(end, operator_period); });
    for (std::thread& worker : workers) worker.join();
    operator_thread.join();
  }

  // Robots that lost their session meanwhile count as errors too.
  void CheckSessions() {
    for (const auto& robot : robots_) {
      if (!robot->failed && robot->session->closed())
        recorder_.Error(robot->id + ": session closed by the gateway");
    }
  }

 private:
  absl::Status SendFrame(FleetRobot& robot) {
    absl::StatusOr<semnav::mapping::v1::FrameAck> ack =
        robot.frames->Send(loop::EncodeFrame(robot.sim->Capture(), robot.id));
    return ack.ok() ? absl::OkStatus() : ack.status();
  }

  // "find a <label>", a different label per robot and task, through OperatorService.
  absl::Status SubmitTask(FleetRobot& robot) {
    const std::string& target =
        shared_.labels[(robot.index * 3 + robot.tasks) % shared_.labels.size()];
    api::SubmitInstructionRequest request;
    request.set_request_id(
        absl::StrCat(robot.id, "-task-", robot.tasks, "-", absl::ToUnixNanos(absl::Now())));
    request.set_robot_id(robot.id);
    request.set_instruction(loop::SearchInstruction(target));
    *request.mutable_search_area() = loop::SearchAreaOf(shared_.world);
    api::SubmitInstructionResponse response;
    grpc::ClientContext context;
    context.set_deadline(absl::ToChronoTime(absl::Now() + kRpcDeadline));
    ++robot.tasks;
    robot.submitted_at = absl::Now();
    robot.first_command_seen = false;
    const grpc::Status status = operator_->SubmitInstruction(&context, request, &response);
    if (!status.ok()) {
      return absl::UnavailableError(absl::StrCat("SubmitInstruction: ", status.error_message()));
    }
    recorder_.TaskSubmitted();
    absl::MutexLock lock(&robot.task_mu);
    robot.task_id = response.task().task_id();
    robot.task_over = false;
    return absl::OkStatus();
  }

  void Fail(FleetRobot& robot, const absl::Status& status) {
    recorder_.Error(absl::StrCat(robot.id, ": ", status.ToString()));
    robot.failed = true;
  }

  // Worker `w` steps robots w, w + threads, ... each when it is due.
  void StepRobots(int w, int threads, absl::Time end) {
    std::vector<FleetRobot*> mine;
    for (size_t i = w; i < robots_.size(); i += threads) mine.push_back(robots_[i].get());
    while (true) {
      FleetRobot* due = nullptr;
      for (FleetRobot* robot : mine) {
        if (!robot->failed && (due == nullptr || robot->next_step < due->next_step)) due = robot;
      }
      if (due == nullptr || due->next_step >= end) return;
      std::this_thread::sleep_until(absl::ToChronoTime(due->next_step));
      if (absl::Status s = Step(*due); !s.ok()) Fail(*due, s);
      due->next_step += kStep;
      // A robot more than a step behind real time skips ahead rather than stepping in a burst.
      if (const absl::Time now = absl::Now(); due->next_step < now - kStep) {
        recorder_.LateStep();
        due->next_step = now;
      }
    }
  }

  absl::Status Step(FleetRobot& robot) {
    if (robot.session->closed()) return absl::UnavailableError("gateway closed the robot session");
    std::string task_id;
    bool task_over = false;
    {
      absl::MutexLock lock(&robot.task_mu);
      task_id = robot.task_id;
      task_over = robot.task_over;
    }
    for (loop::ReceivedCommand& received :
         robot.session->TakeReceivedCommands(absl::ZeroDuration())) {
      const api::RobotCommand& command = received.command;
      if (!robot.first_command_seen && command.task_id() == task_id) {
        recorder_.Instruction(received.received_at - robot.submitted_at);
        robot.first_command_seen = true;
      }
      // The answer to the robot's report: the task's next command after it.
      if (robot.report_sent_at.has_value() && robot.current.has_value() &&
          command.task_id() == robot.current->task_id() &&
          command.command_id() > robot.current->command_id() &&
          received.received_at >= *robot.report_sent_at) {
        recorder_.Feedback(received.received_at - *robot.report_sent_at, robot.current->reason(),
                           command.reason());
      }
      robot.report_sent_at.reset();
      robot.current = command;
      const absl::Time accepted_at = absl::Now();
      const loop::Feedback accepted = robot.executor->Start(KeepAlive(command));
      if (absl::Status s = robot.session->Send(loop::FeedbackMessage(accepted)); !s.ok()) return s;
      if (accepted.kind == api::FEEDBACK_KIND_FAILED && AnsweredOnReport(command))
        robot.report_sent_at = accepted_at;  // refused at once: the gateway re-plans
    }
    if (std::optional<loop::Feedback> outcome = robot.executor->Step(kStepS); outcome.has_value()) {
      const absl::Time sent_at = absl::Now();  // before the write: its time is part of the latency
      if (absl::Status s = robot.session->Send(loop::FeedbackMessage(*outcome)); !s.ok()) return s;
      if (EndsCommand(outcome->kind) && robot.current.has_value() &&
          outcome->command_id == robot.current->command_id() && AnsweredOnReport(*robot.current)) {
        robot.report_sent_at = sent_at;
      }
    }
    if (absl::Status s = robot.session->Send(loop::StateMessage(*robot.sim, robot.id)); !s.ok())
      return s;
    if (++robot.step % kStepsPerFrame == 0) {
      if (absl::Status s = SendFrame(robot); !s.ok()) return s;
    }
    // The operator saw the task end: the robot gets its next search.
    if (task_over) return SubmitTask(robot);
    return absl::OkStatus();
  }

  // The operator: GetTask of every robot's task each period, timed one by one.
  void PollTasks(absl::Time end, absl::Duration period) {
    for (absl::Time round = absl::Now(); round < end; round += period) {
      absl::SleepFor(round - absl::Now());
      for (const auto& robot : robots_) {
        std::string task_id;
        {
          absl::MutexLock lock(&robot->task_mu);
          if (robot->task_over || robot->task_id.empty()) continue;
          task_id = robot->task_id;
        }
        api::GetTaskRequest request;
        request.set_task_id(task_id);
        api::GetTaskResponse response;
        grpc::ClientContext context;
        context.set_deadline(absl::ToChronoTime(absl::Now() + kRpcDeadline));
        const absl::Time sent = absl::Now();
        const grpc::Status status = operator_->GetTask(&context, request, &response);
        const absl::Time answered = absl::Now();
        if (!status.ok()) {
          recorder_.Error(absl::StrCat("GetTask ", task_id, ": ", status.error_message()));
          continue;
        }
        recorder_.Operator(answered - sent);
        if (Terminal(response.task().status())) {
          recorder_.TaskEnded(response.task().status());
          absl::MutexLock lock(&robot->task_mu);
          if (robot->task_id == task_id) robot->task_over = true;
        }
      }
    }
  }

  const SharedWorld& shared_;
  loop::Endpoints endpoints_;
  Recorder& recorder_;
  std::unique_ptr<api::OperatorService::Stub> operator_;
  std::vector<std::unique_ptr<FleetRobot>> robots_;
};

// The live map's size at one time (GetSceneGraph, GetGridMap's explored layer): what mapping's
// memory should follow while the robots explore a finite home.
struct MapSize {
  double at_s = 0.0;  // seconds into the run
  long objects = 0;
  long relations = 0;
  long explored_cells = 0;
  std::map<std::string, long> objects_by_label;  // to compare with the home's own objects
};

std::optional<MapSize> SampleMap(const std::shared_ptr<grpc::Channel>& mapping) {
  auto stub = semnav::mapping::v1::MappingService::NewStub(mapping);
  MapSize size;
  {
    grpc::ClientContext context;
    context.set_deadline(absl::ToChronoTime(absl::Now() + kRpcDeadline));
    semnav::mapping::v1::GetSceneGraphResponse response;
    if (!stub->GetSceneGraph(&context, {}, &response).ok()) return std::nullopt;
    size.objects = response.graph().objects_size();
    size.relations = response.graph().relations_size();
    for (const auto& object : response.graph().objects()) ++size.objects_by_label[object.label()];
  }
  grpc::ClientContext context;
  context.set_deadline(absl::ToChronoTime(absl::Now() + kRpcDeadline));
  semnav::mapping::v1::GetGridMapRequest request;
  request.add_layers(semnav::common::v1::GRID_LAYER_KIND_EXPLORED);
  semnav::mapping::v1::GetGridMapResponse response;
  if (!stub->GetGridMap(&context, request, &response).ok()) return std::nullopt;
  for (const auto& layer : response.grid().layers()) {
    size.explored_cells =
        std::count_if(layer.data().begin(), layer.data().end(), [](char c) { return c != 0; });
  }
  return size;
}

// Seconds into the run when the explored area first stays within kSettledGrowth for
// kSettleWindowS; nullopt when it never did within the run.
std::optional<double> MapSettledAt(const std::vector<MapSize>& sizes) {
  for (size_t i = 0; i < sizes.size(); ++i) {
    for (size_t j = i + 1; j < sizes.size(); ++j) {
      if (sizes[j].explored_cells > (1.0 + kSettledGrowth) * sizes[i].explored_cells) break;
      if (sizes[j].at_s - sizes[i].at_s >= kSettleWindowS) return sizes[i].at_s;
    }
  }
  return std::nullopt;
}

struct ServiceRss {
  long start_kb = 0;              // first sample, robots connected
  long warm_kb = 0;               // first sample after the warm-up share of the run
  long end_kb = 0;                // last sample
  double growth_pct = 0.0;        // warm -> end
  std::vector<long> every_5s_kb;  // one sample per kMapEveryRss, to see the curve
};

struct RunResult {
  int robots = 0;
  double duration_s = 0.0;
  std::vector<double> instruction_ms, feedback_ms, operator_ms;
  std::vector<SlowCommand> slowest;
  int errors = 0;
  std::vector<std::string> error_samples;
  int late_steps = 0;
  int tasks_submitted = 0;
  std::map<std::string, int> tasks_ended;
  std::map<std::string, ServiceRss> rss;
  std::vector<MapSize> map_sizes;  // every kMapPeriod
  double warm_up_s = 0.0;          // RSS growth is counted from here on
  std::optional<double> map_settled_at_s;
  double load_average_1m = 0.0;  // over the machine, at the end of the run

  // Feedback -> next command when there are samples; instruction -> first command otherwise.
  const std::vector<double>& command_ms() const {
    return feedback_ms.empty() ? instruction_ms : feedback_ms;
  }
  std::string command_metric() const {
    return feedback_ms.empty() ? "instruction_to_first_command" : "feedback_to_next_command";
  }
  double rss_growth_pct() const {
    double worst = 0.0;
    for (const auto& [name, r] : rss) worst = std::max(worst, r.growth_pct);
    return worst;
  }
  bool MeetsTargets() const {
    const double command_p99 = Percentile(command_ms(), 99);
    const double operator_p99 = Percentile(operator_ms, 99);
    return errors == 0 && std::isfinite(command_p99) && command_p99 <= kCommandP99TargetMs &&
           std::isfinite(operator_p99) && operator_p99 <= kOperatorP99TargetMs && !rss.empty() &&
           rss_growth_pct() <= kRssGrowthTargetPct;
  }
};

double LoadAverage() {
  std::ifstream file("/proc/loadavg");
  double load = 0.0;
  file >> load;
  return load;
}

absl::StatusOr<RunResult> RunFleet(int robots, absl::Duration duration, const SharedWorld& shared,
                                   int threads, absl::Duration operator_period) {
  const std::string work_dir = (std::filesystem::temp_directory_path() /
                                absl::StrCat("semnav-bench-fleet-", getpid(), "-", robots))
                                   .string();
  std::filesystem::remove_all(work_dir);
  RunResult result;
  result.robots = robots;
  result.duration_s = absl::ToDoubleSeconds(duration);
  {
    loop::SimStackOptions options;
    options.bin_dir = semnav::ExecutableDir();
    options.work_dir = work_dir;
    absl::StatusOr<std::unique_ptr<loop::SimStack>> stack = loop::SimStack::Start(options);
    if (!stack.ok()) return stack.status();
    std::map<std::string, pid_t> pids = (*stack)->service_pids();

    Recorder recorder;
    Fleet fleet(shared, (*stack)->endpoints(), recorder);
    for (int i = 0; i < robots; ++i) {
      if (absl::Status s = fleet.AddRobot(i, robots); !s.ok()) {
        return absl::UnavailableError(absl::StrCat("robot fleet-", i, ": ", s.ToString()));
      }
    }
    const absl::Time begin = absl::Now();
    const absl::Time end = begin + duration;
    std::atomic<bool> sampling{true};
    std::map<std::string, std::vector<std::pair<absl::Time, long>>> samples;
    const std::shared_ptr<grpc::Channel> mapping = (*stack)->endpoints().mapping;
    std::thread sampler([&] {
      for (int i = 0; sampling; ++i) {
        const absl::Time now = absl::Now();
        for (const auto& [name, pid] : pids) {
          if (std::optional<long> kb = RssKb(pid); kb.has_value())
            samples[name].emplace_back(now, *kb);
        }
        if (i % kMapEveryRss == 0) {
          if (std::optional<MapSize> size = SampleMap(mapping)) {
            size->at_s = absl::ToDoubleSeconds(now - begin);
            result.map_sizes.push_back(*size);
          }
        }
        absl::SleepFor(kRssPeriod);
      }
    });
    fleet.Run(end, threads, operator_period);
    fleet.CheckSessions();
    // A service that exited is an error: its RSS can no longer be read.
    for (const auto& [name, pid] : pids) {
      if (!RssKb(pid).has_value()) recorder.Error(name + " exited during the run");
    }
    sampling = false;
    sampler.join();
    result.map_settled_at_s = MapSettledAt(result.map_sizes);
    result.warm_up_s = std::max(absl::ToDoubleSeconds(duration) * kWarmUpShare,
                                result.map_settled_at_s.value_or(0.0));
    const absl::Time warm = begin + absl::Seconds(result.warm_up_s);
    for (const auto& [name, series] : samples) {
      if (series.empty()) continue;
      ServiceRss rss;
      rss.start_kb = series.front().second;
      rss.end_kb = series.back().second;
      rss.warm_kb = rss.end_kb;
      for (const auto& [when, kb] : series) {
        if (when >= warm) {
          rss.warm_kb = kb;
          break;
        }
      }
      rss.growth_pct = 100.0 * (rss.end_kb - rss.warm_kb) / std::max(rss.warm_kb, 1L);
      for (size_t i = 0; i < series.size(); i += kMapEveryRss)
        rss.every_5s_kb.push_back(series[i].second);
      result.rss[name] = rss;
    }
    result.instruction_ms = recorder.instruction_ms();
    result.feedback_ms = recorder.feedback_ms();
    result.slowest = recorder.slowest();
    result.operator_ms = recorder.operator_ms();
    result.errors = recorder.errors();
    result.error_samples = recorder.error_samples();
    result.late_steps = recorder.late_steps();
    result.tasks_submitted = recorder.tasks_submitted();
    result.tasks_ended = recorder.tasks_ended();
    result.load_average_1m = LoadAverage();
  }  // robots disconnect, then the stack stops
  std::filesystem::remove_all(work_dir);
  return result;
}

// A JSON number, or null for a figure without samples.
nlohmann::json Number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json();
}

nlohmann::json RunJson(const RunResult& r) {
  nlohmann::json out;
  out["robots"] = r.robots;
  out["duration_s"] = r.duration_s;
  out["command_metric"] = r.command_metric();
  out["command_ms_p50"] = Number(Percentile(r.command_ms(), 50));
  out["command_ms_p99"] = Number(Percentile(r.command_ms(), 99));
  out["command_samples"] = r.command_ms().size();
  out["feedback_to_command_ms_p50"] = Number(Percentile(r.feedback_ms, 50));
  out["feedback_to_command_ms_p99"] = Number(Percentile(r.feedback_ms, 99));
  out["feedback_to_command_samples"] = r.feedback_ms.size();
  out["command_slowest"] = nlohmann::json::array();
  for (const SlowCommand& slow : r.slowest) {
    out["command_slowest"].push_back(
        {{"ms", slow.ms}, {"reported", slow.reported}, {"next", slow.next}});
  }
  out["instruction_to_command_ms_p50"] = Number(Percentile(r.instruction_ms, 50));
  out["instruction_to_command_ms_p99"] = Number(Percentile(r.instruction_ms, 99));
  out["instruction_to_command_samples"] = r.instruction_ms.size();
  out["operator_ms_p50"] = Number(Percentile(r.operator_ms, 50));
  out["operator_ms_p99"] = Number(Percentile(r.operator_ms, 99));
  out["operator_samples"] = r.operator_ms.size();
  out["errors"] = r.errors;
  out["error_samples"] = r.error_samples;
  out["late_steps"] = r.late_steps;
  out["tasks_submitted"] = r.tasks_submitted;
  out["tasks_ended"] = r.tasks_ended;
  out["rss_growth_pct"] = r.rss_growth_pct();
  out["warm_up_s"] = r.warm_up_s;
  out["map_settled_at_s"] =
      r.map_settled_at_s.has_value() ? nlohmann::json(*r.map_settled_at_s) : nlohmann::json();
  for (const auto& [name, rss] : r.rss) {
    out["services"][name] = {{"rss_start_kb", rss.start_kb},
                             {"rss_warm_kb", rss.warm_kb},
                             {"rss_end_kb", rss.end_kb},
                             {"rss_growth_pct", rss.growth_pct},
                             {"rss_every_5s_kb", rss.every_5s_kb}};
  }
  for (const MapSize& size : r.map_sizes) {
    out["map_sizes"].push_back({{"at_s", size.at_s},
                                {"objects", size.objects},
                                {"relations", size.relations},
                                {"explored_cells", size.explored_cells}});
  }
  if (!r.map_sizes.empty()) out["map_objects_by_label_end"] = r.map_sizes.back().objects_by_label;
  out["meets_targets"] = r.MeetsTargets();
  out["load_average_1m"] = r.load_average_1m;
  return out;
}

void PrintRun(const RunResult& r) {
  auto ms = [](double v) {
    return std::isfinite(v) ? absl::StrFormat("%.1f", v) : std::string("-");
  };
  std::cout << absl::StrFormat(
      "%3d robots %4.0f s | command p50 %s p99 %s ms (%s, %zu) | instruction->command p50 %s p99 "
      "%s ms "
      "(%zu) | operator GetTask p50 %s p99 %s ms (%zu) | errors %d | late steps %d | tasks %d | "
      "rss growth %.1f %% | load %.2f | %s\n",
      r.robots, r.duration_s, ms(Percentile(r.command_ms(), 50)),
      ms(Percentile(r.command_ms(), 99)), r.command_metric(), r.command_ms().size(),
      ms(Percentile(r.instruction_ms, 50)), ms(Percentile(r.instruction_ms, 99)),
      r.instruction_ms.size(), ms(Percentile(r.operator_ms, 50)), ms(Percentile(r.operator_ms, 99)),
      r.operator_ms.size(), r.errors, r.late_steps, r.tasks_submitted, r.rss_growth_pct(),
      r.load_average_1m, r.MeetsTargets() ? "meets targets" : "misses targets");
  std::cout << absl::StrFormat("    warm-up %.0f s (map settled %s)\n", r.warm_up_s,
                               r.map_settled_at_s.has_value()
                                   ? absl::StrFormat("at %.0f s", *r.map_settled_at_s)
                                   : std::string("never"));
  for (const auto& [name, rss] : r.rss) {
    std::cout << absl::StrFormat(
        "    %-10s RSS start %7ld KiB, after warm-up %7ld KiB, end %7ld KiB (%+.1f %%)\n", name,
        rss.start_kb, rss.warm_kb, rss.end_kb, rss.growth_pct);
  }
  for (const SlowCommand& slow : r.slowest) {
    std::cout << absl::StrFormat("    slow command %.1f ms: \"%s\" reported -> \"%s\"\n", slow.ms,
                                 slow.reported, slow.next);
  }
  for (const std::string& error : r.error_samples) std::cout << "    error: " << error << "\n";
}

int Fail(const absl::Status& status) {
  std::cerr << "semnav-bench-fleet: " << status << "\n";
  return absl::IsInvalidArgument(status) ? 2 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const semnav::ParsedFlags flags = semnav::ParseFlagsOrExit(
      argc, argv, kFlags, "semnav-bench-fleet",
      absl::StrCat(
          "usage: semnav-bench-fleet [flags]\n", semnav::FlagsHelp(kFlags),
          "Starts mapping, planning and the gateway beside this binary, runs the robots in "
          "real time and prints one line per run; targets: command p99 <= 50 ms, operator "
          "GetTask p99 <= 10 ms, 0 errors, RSS growth <= 5 %.\n"));
  std::vector<int> counts;
  if (flags.Has("sweep") && flags.Has("robots")) {
    return Fail(absl::InvalidArgumentError("--robots and --sweep: give one of them"));
  }
  if (auto sweep = flags.Get("sweep")) {
    for (absl::string_view part : absl::StrSplit(*sweep, ',')) {
      int n = 0;
      if (!absl::SimpleAtoi(part, &n) || n < 1)
        return Fail(absl::InvalidArgumentError("--sweep: counts >= 1"));
      counts.push_back(n);
    }
  } else {
    int n = 5;
    if (auto v = flags.Get("robots"); v && (!absl::SimpleAtoi(*v, &n) || n < 1)) {
      return Fail(absl::InvalidArgumentError("--robots: must be a number >= 1"));
    }
    counts.push_back(n);
  }
  std::sort(counts.begin(), counts.end());
  double duration_s = 60;
  if (auto v = flags.Get("duration-s");
      v && (!absl::SimpleAtod(*v, &duration_s) || duration_s <= 0)) {
    return Fail(absl::InvalidArgumentError("--duration-s: must be a number > 0"));
  }
  uint64_t world_seed = 7;
  if (auto v = flags.Get("world-seed"); v && !absl::SimpleAtoi(*v, &world_seed)) {
    return Fail(absl::InvalidArgumentError("--world-seed: not a number"));
  }
  int threads = 8;
  if (auto v = flags.Get("robot-threads"); v && (!absl::SimpleAtoi(*v, &threads) || threads < 1)) {
    return Fail(absl::InvalidArgumentError("--robot-threads: must be a number >= 1"));
  }
  int poll_ms = 500;
  if (auto v = flags.Get("operator-poll-ms");
      v && (!absl::SimpleAtoi(*v, &poll_ms) || poll_ms < 1)) {
    return Fail(absl::InvalidArgumentError("--operator-poll-ms: must be a number >= 1"));
  }

  SharedWorld shared;
  shared.world = sim::GenerateIndoor(absl::StrCat("fleet_home_", world_seed), sim::IndoorOptions{},
                                     world_seed);
  if (shared.world.starts.empty())
    return Fail(absl::InternalError("the generated home has no start"));
  shared.scene = std::make_unique<sim::Scene>(sim::Scene::Build(shared.world));
  std::set<std::string> labels;
  for (const sim::ObjectInstance& object : shared.world.objects) labels.insert(object.label);
  shared.labels.assign(labels.begin(), labels.end());
  if (shared.labels.empty()) return Fail(absl::InternalError("the generated home has no objects"));
  std::cout << absl::StrFormat("world %s: %zu starts, %zu object labels; %d cores, load %.2f\n",
                               shared.world.name, shared.world.starts.size(), shared.labels.size(),
                               std::thread::hardware_concurrency(), LoadAverage());

  std::vector<RunResult> runs;
  int max_meeting = 0;
  for (int n : counts) {
    absl::StatusOr<RunResult> run =
        RunFleet(n, absl::Seconds(duration_s), shared, threads, absl::Milliseconds(poll_ms));
    if (!run.ok()) return Fail(run.status());
    PrintRun(*run);
    if (run->MeetsTargets()) max_meeting = std::max(max_meeting, n);
    runs.push_back(*std::move(run));
  }
  std::cout << "max robots meeting targets: " << max_meeting << "\n";
  if (auto path = flags.Get("json")) {
    // The largest run's figures at the top level; a sweep lists every run under "runs".
    nlohmann::json out = RunJson(runs.back());
    out["max_robots_meeting_targets"] = max_meeting;
    std::map<std::string, long> world_objects;
    for (const sim::ObjectInstance& object : shared.world.objects) ++world_objects[object.label];
    out["world_objects_by_label"] = world_objects;
    if (runs.size() > 1) {
      for (const RunResult& r : runs) out["runs"].push_back(RunJson(r));
    }
    std::ofstream file(*path);
    file << out.dump(2) << "\n";
    if (!file) return Fail(absl::InternalError("cannot write " + *path));
  }
  return 0;
}
