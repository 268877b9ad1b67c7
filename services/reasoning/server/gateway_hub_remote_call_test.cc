// No lock across a remote call (issue 18, item 5): a planning service that takes 2 s over one
// robot's path delays neither another robot's command nor an operator's GetTask. Real gRPC on
// loopback on both sides: planning is an in-process PlanningService, operators call the
// gateway's OperatorService; the robot sessions are recording sinks on the hub.
#include <grpcpp/grpcpp.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "absl/synchronization/mutex.h"
#include "absl/synchronization/notification.h"
#include "gtest/gtest.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_test_support.h"
#include "services/reasoning/server/operator_service.h"
#include "services/reasoning/server/planning_client.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

namespace pb = ::semnav::planning::v1;
using Clock = std::chrono::steady_clock;

constexpr auto kStall = std::chrono::seconds(2);
constexpr auto kPrompt = std::chrono::milliseconds(200);

// Paths from x < 0 take kStall; others are answered at once with the straight line.
class StallingPlanning final : public pb::PlanningService::Service {
 public:
  grpc::Status PlanPath(grpc::ServerContext*, const pb::PlanPathRequest* request,
                        pb::PlanPathResponse* response) override {
    if (request->start().x() < 0.0) {
      stall_started.Notify();
      std::this_thread::sleep_for(kStall);
      stall_ended = true;
    }
    *response->add_path() = request->start();
    *response->add_path() = request->goal();
    return grpc::Status::OK;
  }
  absl::Notification stall_started;
  std::atomic<bool> stall_ended{false};
};

std::unique_ptr<grpc::Server> Serve(grpc::Service* service, int* port) {
  grpc::ServerBuilder builder;
  builder.AddListeningPort("127.0.0.1:0", grpc::InsecureServerCredentials(), port);
  builder.RegisterService(service);
  return builder.BuildAndStart();
}

std::shared_ptr<grpc::Channel> Connect(int port) {
  auto channel =
      grpc::CreateChannel("127.0.0.1:" + std::to_string(port), grpc::InsecureChannelCredentials());
  EXPECT_TRUE(
      channel->WaitForConnected(std::chrono::system_clock::now() + std::chrono::seconds(5)));
  return channel;
}

api::SubmitInstructionRequest FindTheSofa(const std::string& robot_id) {
  api::SubmitInstructionRequest request;
  request.set_request_id("find-" + robot_id);
  request.set_robot_id(robot_id);
  request.set_instruction("find the sofa");
  return request;
}

TEST(GatewayHubRemoteCallTest, SlowPlanningForOneRobotDelaysNeitherAnotherRobotNorGetTask) {
  StallingPlanning planning;
  int planning_port = 0;
  std::unique_ptr<grpc::Server> planning_server = Serve(&planning, &planning_port);
  PlanningSettings settings;
  settings.deadline_ms = 10000;  // the stall is an answer, not a timeout
  PlanningClient planner(Connect(planning_port), settings);

  auto hub = std::make_shared<GatewayHub>(GatewayConfig{}, &ShippedLexicon(), &planner,
                                          GatewayBackends{&planner, nullptr, nullptr});
  hub->OnSceneGraph(SofaScene());  // the sofa at (1.0, 0.5): "find the sofa" navigates at once
  OperatorServiceImpl operator_service(hub);
  int gateway_port = 0;
  std::unique_ptr<grpc::Server> gateway_server = Serve(&operator_service, &gateway_port);
  auto operators = api::OperatorService::NewStub(Connect(gateway_port));

  RecordingSink slow_session;  // its path takes kStall
  RecordingSink quick_session;
  for (auto [robot_id, session, x] :
       {std::tuple{"slow", &slow_session, -4.0}, {"quick", &quick_session, 6.0}}) {
    api::SessionHello hello;
    hello.set_robot_id(robot_id);
    ASSERT_TRUE(hub->OpenSession(hello, session).ok());
    ASSERT_TRUE(hub->OnRobotState(session, At(x, 0.5)).ok());
  }

  grpc::Status slow_status;
  api::SubmitInstructionResponse slow_response;
  std::thread slow_submit([&] {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(20));
    slow_status = operators->SubmitInstruction(&context, FindTheSofa("slow"), &slow_response);
  });
  ASSERT_TRUE(planning.stall_started.WaitForNotificationWithTimeout(absl::Seconds(10)));

  // The other robot's task starts and its robot gets the navigate command while the stall lasts.
  const Clock::time_point submitted = Clock::now();
  {
    grpc::ClientContext context;
    api::SubmitInstructionResponse response;
    const grpc::Status status =
        operators->SubmitInstruction(&context, FindTheSofa("quick"), &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
  }
  EXPECT_LT(Clock::now() - submitted, kPrompt);
  const api::RobotCommand quick_command = quick_session.Last();
  ASSERT_TRUE(quick_command.has_navigate()) << quick_command.ShortDebugString();
  EXPECT_EQ(quick_command.navigate().path_size(), 2);  // planned by the (quick) planning service
  // Its next state is handled at once too.
  const Clock::time_point stepped = Clock::now();
  ASSERT_TRUE(hub->OnRobotState(&quick_session, At(5.5, 0.5)).ok());
  EXPECT_LT(Clock::now() - stepped, kPrompt);

  // GetTask answers for the stalled task (task-1, created before its planning call) and the other.
  for (const char* task_id : {"task-1", "task-2"}) {
    const Clock::time_point asked = Clock::now();
    grpc::ClientContext context;
    api::GetTaskRequest request;
    request.set_task_id(task_id);
    api::GetTaskResponse response;
    const grpc::Status status = operators->GetTask(&context, request, &response);
    ASSERT_TRUE(status.ok()) << task_id << ": " << status.error_message();
    EXPECT_LT(Clock::now() - asked, kPrompt) << task_id;
    EXPECT_EQ(response.task().robot_id(), task_id == std::string("task-1") ? "slow" : "quick");
  }
  EXPECT_FALSE(planning.stall_ended)
      << "the checks above ran after the stall: the test measured nothing";

  slow_submit.join();
  ASSERT_TRUE(slow_status.ok()) << slow_status.error_message();
  EXPECT_EQ(slow_response.task_id(), "task-1");
  const api::RobotCommand slow_command = slow_session.Last();
  ASSERT_TRUE(slow_command.has_navigate()) << slow_command.ShortDebugString();
  EXPECT_EQ(slow_command.navigate().path_size(), 2);  // the stalled answer still drives its robot

  gateway_server->Shutdown();
  hub->Shutdown();
  planning_server->Shutdown();
}

// An emergency stop reaches a robot whose task is inside a planning call at once, and the plan
// that comes back afterwards never reaches the robot; the task ends CANCELLED.
TEST(GatewayHubRemoteCallTest, EmergencyStopDuringAPlanningCallIsSentAtOnceAndThePlanIsDropped) {
  StallingPlanning planning;
  int planning_port = 0;
  std::unique_ptr<grpc::Server> planning_server = Serve(&planning, &planning_port);
  PlanningSettings settings;
  settings.deadline_ms = 10000;
  PlanningClient planner(Connect(planning_port), settings);
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner,
                 GatewayBackends{&planner, nullptr, nullptr});
  hub.OnSceneGraph(SofaScene());
  RecordingSink session;
  api::SessionHello hello;
  hello.set_robot_id("slow");
  ASSERT_TRUE(hub.OpenSession(hello, &session).ok());
  ASSERT_TRUE(hub.OnRobotState(&session, At(-4.0, 0.5)).ok());

  std::thread submit([&] { EXPECT_TRUE(hub.Submit(FindTheSofa("slow")).ok()); });
  ASSERT_TRUE(planning.stall_started.WaitForNotificationWithTimeout(absl::Seconds(10)));
  absl::StatusOr<api::EmergencyStopResponse> stopped;
  std::thread stop([&] {
    api::EmergencyStopRequest request;
    request.set_request_id("stop-1");
    request.set_robot_id("slow");
    request.set_reason("operator");
    stopped = hub.EmergencyStop(request);
  });
  const Clock::time_point asked = Clock::now();
  while (Clock::now() - asked < kPrompt) {
    const std::vector<api::ConnectResponse> sent = session.messages();
    if (sent.back().command().stop().emergency()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(session.Last().stop().emergency()) << "no stop within 200 ms of the request";
  EXPECT_FALSE(planning.stall_ended);

  submit.join();
  stop.join();
  ASSERT_TRUE(stopped.ok()) << stopped.status();
  EXPECT_EQ(stopped->stopped_robot_ids_size(), 1);
  ASSERT_EQ(stopped->cancelled_task_ids_size(), 1);  // cancelled once its planning call ended
  EXPECT_EQ(stopped->cancelled_task_ids(0), "task-1");
  EXPECT_TRUE(session.Last().stop().emergency())
      << "the stalled plan reached a stopped robot: " << session.Last().ShortDebugString();
  absl::StatusOr<api::TaskSnapshot> task = hub.GetTask("task-1");
  ASSERT_TRUE(task.ok());
  EXPECT_EQ(task->status(), api::TASK_STATUS_CANCELLED);
  hub.Shutdown();
  planning_server->Shutdown();
}

}  // namespace
}  // namespace semnav::reasoning
