// Contract test: the real semnav-gateway binary on a loopback port, a scripted robot on the
// session stream and an operator through the generated stubs.
#include <grpcpp/grpcpp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <thread>

#include "gtest/gtest.h"
#include "semnav/common/v1/errors.pb.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "semnav/reasoning/v1/robot_session.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "services/reasoning/testing/operator_calls.h"
#include "tests/support/service_process.h"

namespace semnav::reasoning {
namespace {

namespace api = ::semnav::reasoning::v1;

std::chrono::system_clock::time_point Deadline() {
  return std::chrono::system_clock::now() + std::chrono::seconds(20);
}

// A robot that says hello, reports poses and answers commands on its session stream.
class ScriptedRobot {
 public:
  ScriptedRobot(const std::shared_ptr<grpc::Channel>& channel, const std::string& robot_id)
      : stub_(api::RobotSessionService::NewStub(channel)) {
    context_.set_deadline(Deadline());
    stream_ = stub_->Connect(&context_);
    api::ConnectRequest hello;
    hello.mutable_hello()->set_robot_id(robot_id);
    hello.mutable_hello()->mutable_capabilities()->add_modes(api::LOCOMOTION_MODE_GROUND);
    stream_->Write(hello);
    api::ConnectResponse first;
    EXPECT_TRUE(stream_->Read(&first));
    EXPECT_TRUE(first.has_accepted());
    accepted_ = first.accepted();
    ReportPose(0.0, 0.0);
  }
  ~ScriptedRobot() { Leave(); }

  void ReportPose(double x, double y) {
    api::ConnectRequest state;
    state.mutable_state()->mutable_pose()->mutable_position()->set_x(x);
    state.mutable_state()->mutable_pose()->mutable_position()->set_y(y);
    state.mutable_state()->mutable_pose()->mutable_orientation()->set_w(1.0);
    stream_->Write(state);
  }
  api::RobotCommand NextCommand() {
    api::ConnectResponse response;
    EXPECT_TRUE(stream_->Read(&response));
    EXPECT_TRUE(response.has_command());
    return response.command();
  }
  void Report(const api::RobotCommand& command, api::FeedbackKind kind) {
    api::ConnectRequest feedback;
    feedback.mutable_feedback()->set_command_id(command.command_id());
    feedback.mutable_feedback()->set_kind(kind);
    stream_->Write(feedback);
  }
  void Send(const api::ConnectRequest& request) { stream_->Write(request); }
  // The next command, or false when the gateway ended the stream.
  bool TryNextCommand(api::RobotCommand* command) {
    api::ConnectResponse response;
    if (!stream_->Read(&response)) return false;
    EXPECT_TRUE(response.has_command());
    *command = response.command();
    return true;
  }
  // Ends the session and returns the gateway's final status.
  grpc::Status Leave() {
    if (left_) return final_status_;
    left_ = true;
    stream_->WritesDone();
    api::ConnectResponse ignored;
    while (stream_->Read(&ignored)) {
    }
    final_status_ = stream_->Finish();
    return final_status_;
  }
  const api::SessionAccepted& accepted() const { return accepted_; }

 private:
  std::unique_ptr<api::RobotSessionService::Stub> stub_;
  grpc::ClientContext context_;
  std::unique_ptr<grpc::ClientReaderWriter<api::ConnectRequest, api::ConnectResponse>> stream_;
  api::SessionAccepted accepted_;
  bool left_ = false;
  grpc::Status final_status_;
};

class GatewayContractTest : public ::testing::Test {
 protected:
  void SetUp() override {
    absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> process =
        semnav::testing::ServiceProcess::Start("semnav-gateway");
    ASSERT_TRUE(process.ok()) << process.status();
    process_ = *std::move(process);
    operator_ = api::OperatorService::NewStub(process_->channel());
  }

  grpc::Status Submit(const std::string& request_id, const std::string& instruction,
                      api::SubmitInstructionResponse* response, const std::string& lease_id = "") {
    api::SubmitInstructionRequest request;
    request.set_request_id(request_id);
    request.set_robot_id("r1");
    request.set_instruction(instruction);
    request.set_lease_id(lease_id);
    grpc::ClientContext context;
    return operator_->SubmitInstruction(&context, request, response);
  }
  api::TaskSnapshot Get(const std::string& task_id) {
    absl::StatusOr<api::TaskSnapshot> task = reasoning::testing::FetchTask(*operator_, task_id);
    EXPECT_TRUE(task.ok()) << task.status();
    return task.ok() ? *task : api::TaskSnapshot();
  }

  std::unique_ptr<semnav::testing::ServiceProcess> process_;
  std::unique_ptr<api::OperatorService::Stub> operator_;
};

TEST_F(GatewayContractTest, RobotReceivesCommandsUntilSuccessAndWatchSeesIt) {
  ScriptedRobot robot(process_->channel(), "r1");
  api::SubmitInstructionResponse submitted;
  ASSERT_TRUE(Submit("req-1", "look around, then wait", &submitted).ok());
  ASSERT_EQ(submitted.task().subgoals_size(), 2);
  EXPECT_EQ(submitted.task().subgoals(0).type(), api::SUBGOAL_TYPE_LOOK_AROUND);

  api::RobotCommand rotate = robot.NextCommand();
  ASSERT_TRUE(rotate.has_rotate());
  EXPECT_DOUBLE_EQ(rotate.rotate().angular_speed_rps(), 0.5);
  EXPECT_DOUBLE_EQ(rotate.rotate().duration_s(), 12.0);
  EXPECT_EQ(rotate.task_id(), submitted.task_id());
  robot.Report(rotate, api::FEEDBACK_KIND_GOAL_REACHED);
  api::RobotCommand hold = robot.NextCommand();
  ASSERT_TRUE(hold.has_hold());
  EXPECT_DOUBLE_EQ(hold.hold().duration_s(), 5.0);
  robot.Report(hold, api::FEEDBACK_KIND_GOAL_REACHED);
  EXPECT_TRUE(robot.NextCommand().has_stop());

  // WatchTask from revision 0 gets the final snapshot and ends OK.
  api::WatchTaskRequest watch;
  watch.set_task_id(submitted.task_id());
  grpc::ClientContext context;
  context.set_deadline(Deadline());
  auto reader = operator_->WatchTask(&context, watch);
  api::WatchTaskResponse last;
  for (api::WatchTaskResponse update; reader->Read(&update);) last = update;
  EXPECT_TRUE(reader->Finish().ok());
  EXPECT_EQ(last.task().status(), api::TASK_STATUS_SUCCEEDED);
  EXPECT_EQ(last.task().current_subgoal(), 2);
  EXPECT_DOUBLE_EQ(last.task().progress(), 1.0);

  // The event log replays the story: created, subgoal changes, and the final status.
  api::StreamEventsRequest events;
  events.set_robot_id("r1");
  events.set_last_event_id(1);
  grpc::ClientContext events_context;
  events_context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(3));
  auto event_reader = operator_->StreamEvents(&events_context, events);
  std::vector<api::EventKind> kinds;
  for (api::StreamEventsResponse event;
       kinds.empty() || kinds.back() != api::EVENT_KIND_TASK_STATUS;) {
    ASSERT_TRUE(event_reader->Read(&event));
    kinds.push_back(event.event().kind());
    if (kinds.back() == api::EVENT_KIND_TASK_STATUS) {
      EXPECT_EQ(event.event().message().rfind("TASK_STATUS_SUCCEEDED", 0), 0u)
          << event.event().message();
    }
  }
  EXPECT_NE(std::find(kinds.begin(), kinds.end(), api::EVENT_KIND_TASK_CREATED), kinds.end());
  EXPECT_NE(std::find(kinds.begin(), kinds.end(), api::EVENT_KIND_SUBGOAL), kinds.end());
  events_context.TryCancel();
}

TEST_F(GatewayContractTest, SearchWithoutMapExploresAndCancelStops) {
  ScriptedRobot robot(process_->channel(), "r1");
  api::SubmitInstructionResponse submitted;
  ASSERT_TRUE(Submit("req-1", "找红色杯子", &submitted).ok());
  // No planning service: 3 m toward the least-explored sector (east at the start), robot plans.
  api::RobotCommand explore = robot.NextCommand();
  ASSERT_TRUE(explore.has_navigate());
  EXPECT_DOUBLE_EQ(explore.navigate().goal().x(), 3.0);
  EXPECT_DOUBLE_EQ(explore.navigate().goal().y(), 0.0);
  EXPECT_EQ(explore.navigate().path_size(), 0);
  robot.ReportPose(3.0, 0.0);
  robot.Report(explore, api::FEEDBACK_KIND_GOAL_REACHED);
  // No turn at the goal (explore_scan_duration_s 0): the next step follows at once.
  EXPECT_TRUE(robot.NextCommand().has_navigate());
  EXPECT_EQ(Get(submitted.task_id()).phase(), "exploring");

  api::CancelTaskRequest cancel;
  cancel.set_request_id("cancel-1");
  cancel.set_task_id(submitted.task_id());
  api::CancelTaskResponse cancelled;
  grpc::ClientContext context;
  ASSERT_TRUE(operator_->CancelTask(&context, cancel, &cancelled).ok());
  EXPECT_EQ(cancelled.task().status(), api::TASK_STATUS_CANCELLED);
  EXPECT_TRUE(robot.NextCommand().has_stop());
}

TEST_F(GatewayContractTest, LeaseIdempotencyAndFieldErrors) {
  api::AcquireLeaseRequest acquire;
  acquire.set_request_id("lease-1");
  acquire.set_robot_id("r1");
  acquire.set_holder("alice");
  api::AcquireLeaseResponse alice;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(operator_->AcquireLease(&context, acquire, &alice).ok());
  }
  acquire.set_request_id("lease-2");
  acquire.set_holder("bob");
  api::AcquireLeaseResponse bob;
  grpc::ClientContext bob_context;
  EXPECT_EQ(operator_->AcquireLease(&bob_context, acquire, &bob).error_code(),
            grpc::StatusCode::FAILED_PRECONDITION);

  api::SubmitInstructionResponse response;
  grpc::Status no_lease = Submit("req-1", "go to the kitchen", &response);
  EXPECT_EQ(no_lease.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  std::optional<common::v1::ErrorInfo> info = GetDetail<common::v1::ErrorInfo>(no_lease);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->field(), "lease_id");

  api::SubmitInstructionResponse first, again;
  ASSERT_TRUE(Submit("req-2", "go to the kitchen", &first, alice.lease().lease_id()).ok());
  ASSERT_TRUE(Submit("req-2", "something else entirely", &again, alice.lease().lease_id()).ok());
  EXPECT_EQ(again.task_id(), first.task_id());  // a repeated request_id returns the first answer
  EXPECT_EQ(first.task().status(), api::TASK_STATUS_PENDING);  // no robot session yet

  grpc::Status empty = Submit("req-3", "", &response, alice.lease().lease_id());
  EXPECT_EQ(empty.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(empty)->field(), "instruction");

  api::GetTaskRequest unknown;
  unknown.set_task_id("task-999");
  api::GetTaskResponse ignored;
  grpc::ClientContext context;
  EXPECT_EQ(operator_->GetTask(&context, unknown, &ignored).error_code(),
            grpc::StatusCode::NOT_FOUND);
}

TEST_F(GatewayContractTest, EmergencyStopWinsUntilCleared) {
  ScriptedRobot robot(process_->channel(), "r1");
  api::SubmitInstructionResponse submitted;
  ASSERT_TRUE(Submit("req-1", "find the bottle", &submitted).ok());
  EXPECT_TRUE(robot.NextCommand().has_navigate());

  api::EmergencyStopRequest stop;
  stop.set_request_id("stop-1");
  stop.set_reason("person in the way");
  api::EmergencyStopResponse stopped;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(operator_->EmergencyStop(&context, stop, &stopped).ok());
  }
  ASSERT_EQ(stopped.cancelled_task_ids_size(), 1);
  api::RobotCommand command = robot.NextCommand();
  ASSERT_TRUE(command.has_stop());
  EXPECT_TRUE(command.stop().emergency());
  EXPECT_EQ(Get(submitted.task_id()).status(), api::TASK_STATUS_CANCELLED);

  api::SubmitInstructionResponse refused;
  EXPECT_EQ(Submit("req-2", "find the bottle", &refused).error_code(),
            grpc::StatusCode::FAILED_PRECONDITION);
  api::ClearEmergencyStopRequest clear;
  clear.set_request_id("clear-1");
  clear.set_robot_id("r1");
  api::ClearEmergencyStopResponse cleared;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(operator_->ClearEmergencyStop(&context, clear, &cleared).ok());
  }
  EXPECT_TRUE(Submit("req-3", "find the bottle", &refused).ok());
  EXPECT_TRUE(robot.NextCommand().has_navigate());
}

TEST_F(GatewayContractTest, LostSessionPausesAndTheTaskResumesOnReconnect) {
  api::SubmitInstructionResponse submitted;
  {
    ScriptedRobot robot(process_->channel(), "r1");
    ASSERT_TRUE(Submit("req-1", "find the bottle", &submitted).ok());
    EXPECT_TRUE(robot.NextCommand().has_navigate());
  }
  EXPECT_EQ(Get(submitted.task_id()).status(), api::TASK_STATUS_PAUSED);
  ScriptedRobot back(process_->channel(), "r1");
  EXPECT_EQ(back.accepted().resumed_task_id(), submitted.task_id());
  EXPECT_TRUE(back.NextCommand().has_navigate());
  EXPECT_EQ(Get(submitted.task_id()).status(), api::TASK_STATUS_RUNNING);

  // The event log replays what happened after event 1.
  api::StreamEventsRequest events;
  events.set_last_event_id(1);
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(2));
  auto reader = operator_->StreamEvents(&context, events);
  api::StreamEventsResponse event;
  ASSERT_TRUE(reader->Read(&event));
  EXPECT_EQ(event.event().event_id(), 2u);
  EXPECT_FALSE(event.replay_truncated());
  context.TryCancel();
}

TEST_F(GatewayContractTest, TelemetryStreams) {
  ScriptedRobot robot(process_->channel(), "r1");
  api::StreamFastTelemetryRequest fast;
  fast.set_robot_id("r1");
  fast.set_max_rate_hz(50);
  grpc::ClientContext fast_context;
  fast_context.set_deadline(Deadline());
  auto fast_reader = operator_->StreamFastTelemetry(&fast_context, fast);
  // The stream is registered once the call is up; keep reporting until a sample arrives.
  api::StreamFastTelemetryResponse sample;
  std::thread reporter([&robot] {
    for (int i = 1; i <= 20; ++i) {
      robot.ReportPose(0.1 * i, 0.0);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
  // The hello pose (x = 0) may still arrive after the subscription; a reported one must follow.
  bool moved = false;
  while (!moved && fast_reader->Read(&sample)) moved = sample.state().pose().position().x() > 0.0;
  reporter.join();
  EXPECT_TRUE(moved);
  fast_context.TryCancel();

  api::StreamSlowTelemetryRequest slow;
  slow.set_robot_id("r1");
  slow.mutable_period()->set_nanos(100000000);
  grpc::ClientContext slow_context;
  slow_context.set_deadline(Deadline());
  auto slow_reader = operator_->StreamSlowTelemetry(&slow_context, slow);
  api::StreamSlowTelemetryResponse status;
  ASSERT_TRUE(slow_reader->Read(&status));
  EXPECT_TRUE(status.session_connected());
  EXPECT_FALSE(status.emergency_stop_active());
  EXPECT_GE(status.topological_nodes(), 1u);
  slow_context.TryCancel();

  slow.mutable_period()->set_nanos(1000000);  // 1 ms: below the 100 ms minimum
  grpc::ClientContext bad_context;
  auto bad_reader = operator_->StreamSlowTelemetry(&bad_context, slow);
  EXPECT_FALSE(bad_reader->Read(&status));
  grpc::Status bad = bad_reader->Finish();
  EXPECT_EQ(bad.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(bad)->field(), "period");
}

TEST_F(GatewayContractTest, DebugDecomposeAndResolve) {
  api::DecomposeInstructionRequest decompose;
  decompose.set_instruction("去厨房找红色杯子");
  api::DecomposeInstructionResponse steps;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(operator_->DecomposeInstruction(&context, decompose, &steps).ok());
  }
  ASSERT_EQ(steps.subgoals_size(), 5);
  EXPECT_EQ(steps.subgoals(0).type(), api::SUBGOAL_TYPE_NAVIGATE);
  EXPECT_TRUE(steps.subgoals(0).target().is_room());
  EXPECT_EQ(steps.subgoals(3).type(), api::SUBGOAL_TYPE_APPROACH);
  EXPECT_DOUBLE_EQ(steps.subgoals(3).distance_m(), 0.5);
  EXPECT_EQ(steps.source(), "rules");

  // Without a mapping service the scene graph is empty: understood, but no candidate.
  api::ResolveTargetRequest resolve;
  resolve.set_robot_id("r1");
  resolve.set_text("去红色灭火器旁边");
  resolve.set_allow_slow_path(true);
  api::ResolveTargetResponse resolved;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(operator_->ResolveTarget(&context, resolve, &resolved).ok());
  }
  EXPECT_EQ(resolved.understood().name(), "fire extinguisher");
  EXPECT_EQ(resolved.understood().relation(), "near");
  EXPECT_FALSE(resolved.has_best_candidate());
  EXPECT_FALSE(resolved.has_target());
  EXPECT_FALSE(resolved.explanation().empty());

  resolve.clear_text();
  grpc::ClientContext context;
  grpc::Status missing = operator_->ResolveTarget(&context, resolve, &resolved);
  EXPECT_EQ(missing.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(missing)->field(), "text");
}

TEST_F(GatewayContractTest, SessionMustStartWithHello) {
  auto stub = api::RobotSessionService::NewStub(process_->channel());
  grpc::ClientContext context;
  context.set_deadline(Deadline());
  auto stream = stub->Connect(&context);
  api::ConnectRequest state;
  state.mutable_state()->mutable_pose()->mutable_orientation()->set_w(1.0);
  stream->Write(state);
  api::ConnectResponse ignored;
  EXPECT_FALSE(stream->Read(&ignored));
  grpc::Status status = stream->Finish();
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(status)->field(), "hello");
}

bool AllFinite(const api::RobotCommand& command) {
  const auto finite = [](const common::v1::Vector3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
  };
  if (command.has_navigate()) {
    const api::NavigateAction& navigate = command.navigate();
    bool ok = finite(navigate.goal()) && std::isfinite(navigate.goal_yaw()) &&
              std::isfinite(navigate.max_speed_mps());
    for (const api::PathWaypoint& point : navigate.path()) ok = ok && finite(point.position());
    return ok;
  }
  if (command.has_rotate()) {
    const api::RotateAction& rotate = command.rotate();
    return std::isfinite(rotate.angular_speed_rps()) && std::isfinite(rotate.duration_s());
  }
  if (command.has_hold()) return std::isfinite(command.hold().duration_s());
  return true;
}

// A robot that loses its localization and reports NaN: the gateway ends the session with
// INVALID_ARGUMENT naming the coordinate, pauses the task, and no command it ever sends carries
// a NaN (the old gateway kept the pose and, at the next exploration step, sent goal (NaN, NaN)).
TEST_F(GatewayContractTest, NanPoseEndsTheSessionAndNoNanCommandReachesTheRobot) {
  api::SubmitInstructionResponse submitted;
  {
    ScriptedRobot robot(process_->channel(), "r1");
    ASSERT_TRUE(Submit("req-1", "find the bottle", &submitted).ok());
    api::RobotCommand command = robot.NextCommand();
    ASSERT_TRUE(command.has_navigate());
    EXPECT_TRUE(AllFinite(command));

    api::ConnectRequest lost;
    lost.mutable_state()->mutable_pose()->mutable_position()->set_x(std::nan(""));
    lost.mutable_state()->mutable_pose()->mutable_position()->set_y(std::nan(""));
    lost.mutable_state()->mutable_pose()->mutable_orientation()->set_w(1.0);
    robot.Send(lost);
    // The robot goes on as if nothing happened: it reaches the goal and the scan, each of which
    // makes the gateway plan its next step from the robot's pose.
    std::vector<api::RobotCommand> after;
    robot.Report(command, api::FEEDBACK_KIND_GOAL_REACHED);
    for (int i = 0; i < 2 && robot.TryNextCommand(&command); ++i) {
      after.push_back(command);
      robot.Report(command, api::FEEDBACK_KIND_GOAL_REACHED);
    }
    for (const api::RobotCommand& sent : after) EXPECT_TRUE(AllFinite(sent)) << sent.DebugString();
    grpc::Status ended = robot.Leave();
    EXPECT_EQ(ended.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << ended.error_message();
    std::optional<common::v1::ErrorInfo> info = GetDetail<common::v1::ErrorInfo>(ended);
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->field(), "state.pose.position.x");
  }
  api::TaskSnapshot task = Get(submitted.task_id());
  EXPECT_EQ(task.status(), api::TASK_STATUS_PAUSED);
  // Back with a good pose, the task resumes with finite commands.
  ScriptedRobot back(process_->channel(), "r1");
  EXPECT_EQ(back.accepted().resumed_task_id(), submitted.task_id());
  api::RobotCommand resumed = back.NextCommand();
  EXPECT_TRUE(resumed.has_navigate());
  EXPECT_TRUE(AllFinite(resumed)) << resumed.DebugString();
}

// Resident set size of a process, kB, from /proc.
long ResidentKb(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

// A 1 MB robot id is refused naming robot_id with a short message, and nothing of it is kept:
// no task, no event, no robot record (the old gateway stored it and grew ~3.5 MB per call).
TEST_F(GatewayContractTest, HugeRobotIdIsRefusedAndNothingIsKept) {
  const std::string huge_id(1 << 20, 'r');
  api::SubmitInstructionRequest submit;
  submit.set_request_id("req-big");
  submit.set_robot_id(huge_id);
  submit.set_instruction("find the bottle");
  api::SubmitInstructionResponse submitted;
  {
    grpc::ClientContext context;
    grpc::Status status = operator_->SubmitInstruction(&context, submit, &submitted);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    std::optional<common::v1::ErrorInfo> info = GetDetail<common::v1::ErrorInfo>(status);
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->field(), "robot_id");
    EXPECT_LT(status.error_message().size(), 1024u);
  }

  const long rss_before = ResidentKb(process_->pid());
  for (int i = 0; i < 20; ++i) {
    api::EmergencyStopRequest stop;
    stop.set_request_id("stop-big-" + std::to_string(i));
    stop.set_robot_id(huge_id + std::to_string(i));
    api::EmergencyStopResponse stopped;
    grpc::ClientContext context;
    grpc::Status status = operator_->EmergencyStop(&context, stop, &stopped);
    ASSERT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    std::optional<common::v1::ErrorInfo> info = GetDetail<common::v1::ErrorInfo>(status);
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->field(), "robot_id");
    EXPECT_LT(status.error_message().size(), 1024u);
  }
  const long rss_after = ResidentKb(process_->pid());
  ASSERT_GT(rss_before, 0);
  // 20 stored ids would be > 60 MB; receive buffers are reused.
  EXPECT_LT(rss_after - rss_before, 20 * 1024) << rss_before << " kB -> " << rss_after << " kB";

  api::ListTasksRequest list;
  api::ListTasksResponse tasks;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(operator_->ListTasks(&context, list, &tasks).ok());
  }
  EXPECT_EQ(tasks.tasks_size(), 0);
  // Clearing it is refused the same way (the old gateway had stored the robot and cleared it).
  api::ClearEmergencyStopRequest clear;
  clear.set_request_id("clear-big");
  clear.set_robot_id(huge_id + "0");
  api::ClearEmergencyStopResponse cleared;
  grpc::ClientContext context;
  EXPECT_EQ(operator_->ClearEmergencyStop(&context, clear, &cleared).error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);
}

// EmergencyStop{robot_id: ""} stops every connected robot: r1 is sent a stop and listed, its task
// cancelled; r2, disconnected with a paused task, is left alone and resumes when it reconnects.
TEST_F(GatewayContractTest, EmergencyStopOfEveryRobotSkipsDisconnectedOnes) {
  api::SubmitInstructionRequest submit;
  submit.set_request_id("req-r2");
  submit.set_robot_id("r2");
  submit.set_instruction("find the bottle");
  api::SubmitInstructionResponse r2_task;
  {
    ScriptedRobot r2(process_->channel(), "r2");
    grpc::ClientContext context;
    ASSERT_TRUE(operator_->SubmitInstruction(&context, submit, &r2_task).ok());
    EXPECT_TRUE(r2.NextCommand().has_navigate());
  }
  ASSERT_EQ(Get(r2_task.task_id()).status(), api::TASK_STATUS_PAUSED);

  ScriptedRobot r1(process_->channel(), "r1");
  api::SubmitInstructionResponse r1_task;
  ASSERT_TRUE(Submit("req-r1", "find the bottle", &r1_task).ok());
  EXPECT_TRUE(r1.NextCommand().has_navigate());

  api::EmergencyStopRequest stop;
  stop.set_request_id("stop-all");
  stop.set_reason("fire alarm");
  api::EmergencyStopResponse stopped;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(operator_->EmergencyStop(&context, stop, &stopped).ok());
  }
  ASSERT_EQ(stopped.stopped_robot_ids_size(), 1);
  EXPECT_EQ(stopped.stopped_robot_ids(0), "r1");
  ASSERT_EQ(stopped.cancelled_task_ids_size(), 1);
  EXPECT_EQ(stopped.cancelled_task_ids(0), r1_task.task_id());
  api::RobotCommand command = r1.NextCommand();
  ASSERT_TRUE(command.has_stop());
  EXPECT_TRUE(command.stop().emergency());
  EXPECT_EQ(Get(r1_task.task_id()).status(), api::TASK_STATUS_CANCELLED);
  EXPECT_EQ(Get(r2_task.task_id()).status(), api::TASK_STATUS_PAUSED);

  ScriptedRobot r2_back(process_->channel(), "r2");
  EXPECT_EQ(r2_back.accepted().resumed_task_id(), r2_task.task_id());
  EXPECT_TRUE(r2_back.NextCommand().has_navigate());
}

// A configured commonsense prior that cannot be read stops the binary with the key named.
TEST(GatewayBinaryTest, UnreadablePriorPathIsAConfigError) {
  const std::string config = ::testing::TempDir() + "/gateway_bad_prior.yaml";
  std::ofstream(config) << "gateway:\n  prior_path: /nonexistent/conceptnet-data.json\n";
  absl::StatusOr<semnav::testing::ProcessResult> run = semnav::testing::RunToCompletion(
      "semnav-gateway", {"--config", config, "--listen", "127.0.0.1:0"});
  ASSERT_TRUE(run.ok()) << run.status();
  EXPECT_EQ(run->exit_code, 2) << run->output;
  EXPECT_NE(run->output.find(
                "prior_path: offline prior file /nonexistent/conceptnet-data.json cannot be read"),
            std::string::npos)
      << run->output;
}

}  // namespace
}  // namespace semnav::reasoning
