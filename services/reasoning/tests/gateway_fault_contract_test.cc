// Fault injection with the real binaries on loopback (issue "Fleet and faults"): semnav-mapping,
// semnav-planning and semnav-gateway, a fake robot session, and planning SIGKILLed mid-task. The
// gateway must pause the task with the robot holding and name planning in the event log, never
// send a navigate goal while planning is dead, and resume with a planned path once planning is
// back on the same port; or fail the task after dependency_timeout_s.
#include <grpcpp/grpcpp.h>
#include <signal.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/time/clock.h"
#include "gtest/gtest.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "semnav/reasoning/v1/robot_session.grpc.pb.h"
#include "services/reasoning/testing/operator_calls.h"
#include "services/reasoning/testing/service_stack.h"
#include "services/reasoning/testing/table_scene_frames.h"
#include "tests/support/service_process.h"

namespace semnav::reasoning {
namespace {

namespace api = ::semnav::reasoning::v1;
using Session = grpc::ClientReaderWriter<api::ConnectRequest, api::ConnectResponse>;

const Eigen::Vector3d kClock(6.0, 1.3, 1.0);
const Eigen::Vector2d kStart(1.5, 1.3);

// Reads the session's commands on a thread, so the test can wait for one with a timeout.
class CommandReader {
 public:
  explicit CommandReader(Session* session)
      : thread_([this, session] {
          api::ConnectResponse response;
          while (session->Read(&response)) {
            if (!response.has_command()) continue;
            std::lock_guard<std::mutex> lock(mu_);
            commands_.push_back(response.command());
            arrived_.notify_all();
          }
        }) {}
  ~CommandReader() { thread_.join(); }  // after the session's context was cancelled

  // The next command, or none within `timeout`.
  std::optional<api::RobotCommand> Next(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mu_);
    if (!arrived_.wait_for(lock, timeout, [this] { return !commands_.empty(); })) {
      return std::nullopt;
    }
    api::RobotCommand command = commands_.front();
    commands_.pop_front();
    return command;
  }

 private:
  std::mutex mu_;
  std::condition_variable arrived_;
  std::deque<api::RobotCommand> commands_;
  std::thread thread_;
};

class GatewayFaultContractTest : public ::testing::Test {
 protected:
  // `executor` holds the gateway's dependency_* keys; a `journal_flush_s` > 0 gives the gateway a
  // state directory (its journal) flushed that often.
  void StartStack(const std::string& executor, double journal_flush_s = 0.0) {
    dir_ = testing::FreshDir("gateway_fault_contract");
    const std::string gateway_extra =
        journal_flush_s > 0.0
            ? absl::StrCat("  state_directory: ", dir_,
                           "/gateway_state\n  journal_flush_interval_s: ", journal_flush_s, "\n")
            : "";
    auto mapping = testing::StartMapping(dir_);
    ASSERT_TRUE(mapping.ok()) << mapping.status();
    mapping_ = *std::move(mapping);
    planning_yaml_ = "planning:\n  mapping:\n    address: " + mapping_->address() + "\n";
    auto planning =
        testing::StartWithConfig("semnav-planning", dir_, "planning.yaml", planning_yaml_);
    ASSERT_TRUE(planning.ok()) << planning.status();
    planning_ = *std::move(planning);
    auto gateway = testing::StartWithConfig(
        "semnav-gateway", dir_, "gateway.yaml",
        absl::StrCat("gateway:\n  mapping:\n    address: ", mapping_->address(),
                     "\n  planning:\n    address: ", planning_->address(), "\n  executor: {",
                     executor, "}\n", gateway_extra));
    ASSERT_TRUE(gateway.ok()) << gateway.status();
    gateway_ = *std::move(gateway);
    operator_ = api::OperatorService::NewStub(gateway_->channel());

    ASSERT_TRUE(testing::StreamLabelledFrames(mapping_->channel(), 1, 6, "clock", kClock).ok());
    ASSERT_TRUE(testing::WaitUntilFastResolvable(*operator_, "r1", "go to the clock", 5000));
    ASSERT_NO_FATAL_FAILURE(OpenSession());
    ASSERT_TRUE(session_->Write(testing::PoseReport(kStart.x(), kStart.y())));
    ASSERT_TRUE(testing::WaitUntilPoseSeen(*operator_, "r1", 5000));
    const absl::StatusOr<std::string> task_id =
        testing::Submit(*operator_, "go-clock", "r1", "go to the clock");
    ASSERT_TRUE(task_id.ok()) << task_id.status();
    task_id_ = *task_id;
  }

  // The robot's session (again after a gateway restart); `accepted_` keeps the gateway's answer.
  void OpenSession() {
    CloseSession();
    session_stub_ = api::RobotSessionService::NewStub(gateway_->channel());
    session_context_ = std::make_unique<grpc::ClientContext>();
    session_context_->set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(90));
    session_ = session_stub_->Connect(session_context_.get());
    api::ConnectRequest hello;
    hello.mutable_hello()->set_robot_id("r1");
    hello.mutable_hello()->mutable_capabilities()->add_modes(api::LOCOMOTION_MODE_GROUND);
    hello.mutable_hello()->mutable_capabilities()->set_footprint_radius_m(0.1);
    ASSERT_TRUE(session_->Write(hello));
    api::ConnectResponse accepted;
    ASSERT_TRUE(session_->Read(&accepted));
    ASSERT_TRUE(accepted.has_accepted());
    accepted_ = accepted.accepted();
    reader_ = std::make_unique<CommandReader>(session_.get());
  }

  void CloseSession() {
    if (session_ != nullptr) {
      session_->WritesDone();
      session_context_->TryCancel();
    }
    reader_.reset();
    session_.reset();
  }

  // The gateway again on its address with its config (and so its state directory).
  void RestartGateway() {
    const std::string address = gateway_->address();
    auto restarted = semnav::testing::ServiceProcess::Start(
        "semnav-gateway", {"--config", dir_ + "/gateway.yaml", "--listen", address});
    ASSERT_TRUE(restarted.ok()) << restarted.status();
    gateway_ = *std::move(restarted);
    operator_ = api::OperatorService::NewStub(gateway_->channel());
  }

  void TearDown() override { CloseSession(); }

  // The first navigate command with a planned path within `timeout`; every command before it
  // must be a hold (the task waiting for planning), never a goal without a path.
  std::optional<api::RobotCommand> NextPlannedNavigate(std::chrono::seconds timeout) {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < until) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          until - std::chrono::steady_clock::now());
      std::optional<api::RobotCommand> command = reader_->Next(left);
      if (!command.has_value()) break;
      if (command->has_navigate() && command->navigate().path_size() >= 2) return command;
      EXPECT_TRUE(command->has_hold()) << command->ShortDebugString();
    }
    return std::nullopt;
  }

  bool Blocked(uint64_t command_id) {
    api::ConnectRequest blocked;
    blocked.mutable_feedback()->set_command_id(command_id);
    blocked.mutable_feedback()->set_kind(api::FEEDBACK_KIND_BLOCKED);
    return session_->Write(blocked);
  }

  // Kills planning (no goodbye) and makes the gateway plan again: the robot reports BLOCKED.
  void KillPlanningAndBlock(uint64_t command_id) {
    ASSERT_EQ(::kill(planning_->pid(), SIGKILL), 0);
    EXPECT_FALSE(planning_->Terminate(absl::Seconds(5)).ok());  // reaped: died from SIGKILL
    ASSERT_TRUE(Blocked(command_id));
  }

  // Task event messages, oldest first.
  std::vector<std::string> EventMessages() {
    api::ListEventsRequest request;
    request.set_task_id(task_id_);
    api::ListEventsResponse response;
    grpc::ClientContext context;
    EXPECT_TRUE(operator_->ListEvents(&context, request, &response).ok());
    std::vector<std::string> messages;
    for (const api::Event& event : response.events()) messages.push_back(event.message());
    return messages;
  }

  bool AnyEventContains(const std::string& text) {
    for (const std::string& message : EventMessages()) {
      if (absl::StrContains(message, text)) return true;
    }
    return false;
  }

  std::string dir_;
  std::string planning_yaml_;
  std::string task_id_;
  std::unique_ptr<semnav::testing::ServiceProcess> mapping_;
  std::unique_ptr<semnav::testing::ServiceProcess> planning_;
  std::unique_ptr<semnav::testing::ServiceProcess> gateway_;
  std::unique_ptr<api::OperatorService::Stub> operator_;
  std::unique_ptr<api::RobotSessionService::Stub> session_stub_;
  std::unique_ptr<grpc::ClientContext> session_context_;
  std::unique_ptr<Session> session_;
  api::SessionAccepted accepted_;
  std::unique_ptr<CommandReader> reader_;
};

TEST_F(GatewayFaultContractTest, PlanningKilledPausesTheTaskHoldingAndItResumesWhenPlanningIsBack) {
  ASSERT_NO_FATAL_FAILURE(StartStack("dependency_retry_s: 0.5, dependency_timeout_s: 60"));
  const std::optional<api::RobotCommand> navigate = NextPlannedNavigate(std::chrono::seconds(15));
  ASSERT_TRUE(navigate.has_value());
  const std::string planning_address = planning_->address();
  ASSERT_NO_FATAL_FAILURE(KillPlanningAndBlock(navigate->command_id()));

  const std::optional<api::RobotCommand> hold = reader_->Next(std::chrono::milliseconds(5000));
  ASSERT_TRUE(hold.has_value());
  EXPECT_TRUE(hold->has_hold()) << hold->ShortDebugString();  // a hold, not an emergency stop
  // Six retries while planning is dead: no command at all, above all no blind navigate goal.
  if (const std::optional<api::RobotCommand> blind =
          reader_->Next(std::chrono::milliseconds(3000))) {
    ADD_FAILURE() << "command while planning is dead: " << blind->ShortDebugString();
  }
  absl::StatusOr<api::TaskSnapshot> paused = testing::FetchTask(*operator_, task_id_);
  ASSERT_TRUE(paused.ok()) << paused.status();
  EXPECT_EQ(paused->status(), api::TASK_STATUS_PAUSED);
  EXPECT_TRUE(absl::StartsWith(paused->reason(), "dependency_unavailable: planning"))
      << paused->reason();
  EXPECT_TRUE(AnyEventContains("TASK_STATUS_PAUSED: dependency_unavailable: planning"))
      << absl::StrJoin(EventMessages(), "\n");

  // Planning back on the same port: the interrupted subgoal goes on with a planned path.
  auto restarted = semnav::testing::ServiceProcess::Start(
      "semnav-planning", {"--config", dir_ + "/planning.yaml", "--listen", planning_address});
  ASSERT_TRUE(restarted.ok()) << restarted.status();
  planning_ = *std::move(restarted);
  // The gateway's channel reconnects with gRPC's backoff (1 s growing by 1.6).
  const std::optional<api::RobotCommand> resumed = NextPlannedNavigate(std::chrono::seconds(40));
  ASSERT_TRUE(resumed.has_value());
  absl::StatusOr<api::TaskSnapshot> running = testing::FetchTask(*operator_, task_id_);
  ASSERT_TRUE(running.ok()) << running.status();
  EXPECT_EQ(running->status(), api::TASK_STATUS_RUNNING);
  EXPECT_TRUE(AnyEventContains("TASK_STATUS_RUNNING: dependency_restored: planning"))
      << absl::StrJoin(EventMessages(), "\n");
}

TEST_F(GatewayFaultContractTest, PlanningKilledForLongerThanTheTimeoutFailsTheTask) {
  // 6 s: long enough that a first PlanPath stalling to its 2 s deadline on a loaded machine
  // (a pause, then a retry) does not fail the task before it moves.
  ASSERT_NO_FATAL_FAILURE(StartStack("dependency_retry_s: 0.5, dependency_timeout_s: 6"));
  const std::optional<api::RobotCommand> navigate = NextPlannedNavigate(std::chrono::seconds(15));
  ASSERT_TRUE(navigate.has_value());
  ASSERT_NO_FATAL_FAILURE(KillPlanningAndBlock(navigate->command_id()));

  const std::optional<api::RobotCommand> hold = reader_->Next(std::chrono::milliseconds(5000));
  ASSERT_TRUE(hold.has_value());
  EXPECT_TRUE(hold->has_hold()) << hold->ShortDebugString();
  const std::optional<api::RobotCommand> stop = reader_->Next(std::chrono::milliseconds(12000));
  ASSERT_TRUE(stop.has_value());
  EXPECT_TRUE(stop->has_stop()) << stop->ShortDebugString();  // nothing in between: no goal
  absl::StatusOr<api::TaskSnapshot> failed = testing::FetchTask(*operator_, task_id_);
  ASSERT_TRUE(failed.ok()) << failed.status();
  EXPECT_EQ(failed->status(), api::TASK_STATUS_FAILED);
  EXPECT_EQ(failed->reason(), "planning unavailable for 6 s");
}

// Mapping gone behind a live planning service: planning answers that its live map's GetGridMap
// failed, and the pause names mapping. A robot on wall time accepts a grid planning fetched up to
// planning.live_map_max_age_ms (500 ms) before, so the re-plan is asked once that grid is older.
TEST_F(GatewayFaultContractTest, MappingKilledPausesTheTaskNamingMapping) {
  ASSERT_NO_FATAL_FAILURE(StartStack("dependency_retry_s: 0.5, dependency_timeout_s: 60"));
  const std::optional<api::RobotCommand> navigate = NextPlannedNavigate(std::chrono::seconds(15));
  ASSERT_TRUE(navigate.has_value());
  ASSERT_EQ(::kill(mapping_->pid(), SIGKILL), 0);
  EXPECT_FALSE(mapping_->Terminate(absl::Seconds(5)).ok());
  absl::SleepFor(absl::Milliseconds(600));
  ASSERT_TRUE(Blocked(navigate->command_id()));

  const std::optional<api::RobotCommand> hold = reader_->Next(std::chrono::milliseconds(5000));
  ASSERT_TRUE(hold.has_value());
  EXPECT_TRUE(hold->has_hold()) << hold->ShortDebugString();
  if (const std::optional<api::RobotCommand> blind =
          reader_->Next(std::chrono::milliseconds(2000))) {
    ADD_FAILURE() << "command while mapping is dead: " << blind->ShortDebugString();
  }
  absl::StatusOr<api::TaskSnapshot> paused = testing::FetchTask(*operator_, task_id_);
  ASSERT_TRUE(paused.ok()) << paused.status();
  EXPECT_EQ(paused->status(), api::TASK_STATUS_PAUSED);
  EXPECT_TRUE(absl::StartsWith(paused->reason(), "dependency_unavailable: mapping"))
      << paused->reason();
  EXPECT_TRUE(AnyEventContains("TASK_STATUS_PAUSED: dependency_unavailable: mapping"))
      << absl::StrJoin(EventMessages(), "\n");
}

// The gateway SIGKILLed mid-task (issue "Fleet and faults"): the restarted gateway knows the task
// and its events from its journal, holds it PAUSED until the robot reports where it is, then goes
// on with a planned path. Nothing is commanded before that first state.
TEST_F(GatewayFaultContractTest, GatewayKilledMidTaskKeepsTheTaskAndResumesOnTheRobotsNextState) {
  ASSERT_NO_FATAL_FAILURE(StartStack("dependency_retry_s: 0.5, dependency_timeout_s: 60", 0.1));
  ASSERT_TRUE(NextPlannedNavigate(std::chrono::seconds(15)).has_value());
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // > the flush interval
  ASSERT_EQ(::kill(gateway_->pid(), SIGKILL), 0);
  EXPECT_FALSE(gateway_->Terminate(absl::Seconds(5)).ok());
  CloseSession();
  ASSERT_NO_FATAL_FAILURE(RestartGateway());

  absl::StatusOr<api::TaskSnapshot> restored = testing::FetchTask(*operator_, task_id_);
  ASSERT_TRUE(restored.ok()) << restored.status();
  EXPECT_EQ(restored->status(), api::TASK_STATUS_PAUSED);
  EXPECT_TRUE(absl::StartsWith(restored->reason(), "gateway_restarted")) << restored->reason();
  EXPECT_EQ(restored->instruction(), "go to the clock");
  const std::vector<std::string> events = EventMessages();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front(), "go to the clock");  // the creation event, from before the crash
  EXPECT_TRUE(AnyEventContains("TASK_STATUS_PAUSED: gateway_restarted"))
      << absl::StrJoin(events, "\n");

  ASSERT_NO_FATAL_FAILURE(OpenSession());
  EXPECT_EQ(accepted_.resumed_task_id(), task_id_);
  if (const std::optional<api::RobotCommand> early =
          reader_->Next(std::chrono::milliseconds(1000))) {
    ADD_FAILURE() << "command before the robot's first state: " << early->ShortDebugString();
  }
  ASSERT_TRUE(session_->Write(testing::PoseReport(kStart.x(), kStart.y())));
  ASSERT_TRUE(NextPlannedNavigate(std::chrono::seconds(15)).has_value());
  absl::StatusOr<api::TaskSnapshot> running = testing::FetchTask(*operator_, task_id_);
  ASSERT_TRUE(running.ok()) << running.status();
  EXPECT_EQ(running->status(), api::TASK_STATUS_RUNNING);
}

// A clean stop ends the gateway's tasks, so a fresh start keeps them as history and never drives
// one.
TEST_F(GatewayFaultContractTest, GatewayStoppedCleanlyCancelsItsTasksAndKeepsThem) {
  ASSERT_NO_FATAL_FAILURE(StartStack("dependency_retry_s: 0.5, dependency_timeout_s: 60", 1.0));
  ASSERT_TRUE(NextPlannedNavigate(std::chrono::seconds(15)).has_value());
  ASSERT_TRUE(gateway_->Terminate(absl::Seconds(10)).ok());  // SIGTERM, exit 0
  CloseSession();
  ASSERT_NO_FATAL_FAILURE(RestartGateway());
  absl::StatusOr<api::TaskSnapshot> kept = testing::FetchTask(*operator_, task_id_);
  ASSERT_TRUE(kept.ok()) << kept.status();
  EXPECT_EQ(kept->status(), api::TASK_STATUS_CANCELLED);
  EXPECT_EQ(kept->reason(), "gateway stopped");
  ASSERT_NO_FATAL_FAILURE(OpenSession());
  EXPECT_EQ(accepted_.resumed_task_id(), "");
  ASSERT_TRUE(session_->Write(testing::PoseReport(kStart.x(), kStart.y())));
  if (const std::optional<api::RobotCommand> command =
          reader_->Next(std::chrono::milliseconds(1500))) {
    ADD_FAILURE() << "a cancelled task commanded the robot: " << command->ShortDebugString();
  }
}

}  // namespace
}  // namespace semnav::reasoning
