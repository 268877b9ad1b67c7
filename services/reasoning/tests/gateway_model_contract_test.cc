// End-to-end contract of the slow path: real semnav-mapping (synthetic frames with a "clock"
// detection), the real semnav-model-proxy with its offline ConceptNet backend (the key-free
// default of the local stack), and semnav-gateway configured with both. "find the red clock" is
// not confident on the fast path (the clock reports no colour: fused 0.43), so the gateway asks
// the proxy while the robot explores; the offline answer (lexical 0.9 x offline factor 0.75 =
// 0.675 >= 0.6) makes the clock the goal, and the robot is driven to it until success.
#include <grpcpp/grpcpp.h>

#include <chrono>

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

const Eigen::Vector3d kClock(6.0, 1.3, 1.0);

class GatewayModelContractTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string dir = testing::FreshDir("gateway_model_contract");
    auto mapping = testing::StartMapping(dir);
    ASSERT_TRUE(mapping.ok()) << mapping.status();
    mapping_ = *std::move(mapping);
    auto proxy = semnav::testing::ServiceProcess::Start("semnav-model-proxy");
    ASSERT_TRUE(proxy.ok()) << proxy.status();
    proxy_ = *std::move(proxy);
    auto gateway =
        testing::StartWithConfig("semnav-gateway", dir, "gateway.yaml",
                                 "gateway:\n  mapping:\n    address: " + mapping_->address() +
                                     "\n  model_proxy:\n    address: " + proxy_->address() + "\n");
    ASSERT_TRUE(gateway.ok()) << gateway.status();
    gateway_ = *std::move(gateway);
    operator_ = api::OperatorService::NewStub(gateway_->channel());
  }

  std::unique_ptr<semnav::testing::ServiceProcess> mapping_;
  std::unique_ptr<semnav::testing::ServiceProcess> proxy_;
  std::unique_ptr<semnav::testing::ServiceProcess> gateway_;
  std::unique_ptr<api::OperatorService::Stub> operator_;
};

TEST_F(GatewayModelContractTest, SlowPathThroughTheOfflineProxyDrivesTheRobotToTheClock) {
  ASSERT_TRUE(testing::StreamLabelledFrames(mapping_->channel(), 1, 6, "clock", kClock).ok());
  // The clock is in the gateway's graph once the plain name resolves on the fast path.
  ASSERT_TRUE(testing::WaitUntilFastResolvable(*operator_, "r1", "go to the clock", 5000));

  // The operator's ResolveTarget runs the same slow path (its reactor finishes on the answer).
  api::ResolveTargetRequest resolve;
  resolve.set_robot_id("r1");
  resolve.set_text("the red clock");
  resolve.set_allow_slow_path(true);
  api::ResolveTargetResponse resolved;
  grpc::ClientContext resolve_context;
  ASSERT_TRUE(operator_->ResolveTarget(&resolve_context, resolve, &resolved).ok());
  EXPECT_EQ(resolved.target().path(), api::RESOLUTION_PATH_SLOW) << resolved.ShortDebugString();
  EXPECT_NEAR(resolved.target().confidence(), 0.9 * 0.75, 1e-9);
  EXPECT_EQ(resolved.grounded_objects(), 1);
  EXPECT_LT(resolved.best_candidate().score().fused(), 0.75);  // not confident on the fast path

  auto session_stub = api::RobotSessionService::NewStub(gateway_->channel());
  grpc::ClientContext session_context;
  session_context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(30));
  auto session = session_stub->Connect(&session_context);
  api::ConnectRequest hello;
  hello.mutable_hello()->set_robot_id("r1");
  ASSERT_TRUE(session->Write(hello));
  api::ConnectResponse message;
  ASSERT_TRUE(session->Read(&message));
  ASSERT_TRUE(message.has_accepted());
  const auto report = [&](const api::RobotCommand& done, double x, double y) {
    ASSERT_TRUE(session->Write(testing::PoseReport(x, y)));
    api::ConnectRequest feedback;
    feedback.mutable_feedback()->set_command_id(done.command_id());
    feedback.mutable_feedback()->set_kind(api::FEEDBACK_KIND_GOAL_REACHED);
    ASSERT_TRUE(session->Write(feedback));
  };
  ASSERT_TRUE(session->Write(testing::PoseReport(1.5, 1.3)));
  ASSERT_TRUE(testing::WaitUntilPoseSeen(*operator_, "r1", 5000));

  const absl::StatusOr<std::string> task_id =
      testing::Submit(*operator_, "find-red-clock", "r1", "find the red clock");
  ASSERT_TRUE(task_id.ok()) << task_id.status();

  // The first command explores: the model's answer is not awaited.
  ASSERT_TRUE(session->Read(&message));
  const api::RobotCommand explore = message.command();
  ASSERT_TRUE(explore.has_navigate()) << explore.ShortDebugString();
  EXPECT_EQ(explore.reason(), "exploring for the target");

  // Then the slow path's goal: APPROACH 0.5 m from the clock at 0.15 m/s.
  ASSERT_TRUE(session->Read(&message));
  const api::RobotCommand approach = message.command();
  ASSERT_TRUE(approach.has_navigate()) << approach.ShortDebugString();
  EXPECT_DOUBLE_EQ(approach.navigate().max_speed_mps(), 0.15);
  absl::StatusOr<api::TaskSnapshot> task = testing::FetchTask(*operator_, *task_id);
  ASSERT_TRUE(task.ok()) << task.status();
  ASSERT_TRUE(task->has_target());
  EXPECT_EQ(task->target().path(), api::RESOLUTION_PATH_SLOW);
  EXPECT_NEAR(task->target().confidence(), 0.9 * 0.75, 1e-9);  // offline answer, weighed lower
  EXPECT_EQ(task->model_requests(), 1);
  EXPECT_EQ(task->model_calls(), 2);  // Complete + Embed (which the offline proxy cannot answer)
  const Eigen::Vector2d close(approach.navigate().goal().x(), approach.navigate().goal().y());
  EXPECT_NEAR(
      (close - Eigen::Vector2d(task->target().position().x(), task->target().position().y()))
          .norm(),
      0.5, 1e-6);
  report(approach, close.x(), close.y());

  // VERIFY: two new detections confirm the clock; then STOP within 1 m.
  ASSERT_TRUE(session->Read(&message));
  ASSERT_TRUE(message.command().has_navigate()) << message.command().ShortDebugString();
  report(message.command(), close.x(), close.y());
  ASSERT_TRUE(session->Read(&message));  // facing it: hold while detections confirm it
  EXPECT_TRUE(message.command().has_hold()) << message.command().ShortDebugString();
  ASSERT_TRUE(testing::StreamLabelledFrames(mapping_->channel(), 7, 2, "clock", kClock).ok());
  ASSERT_TRUE(session->Read(&message));
  EXPECT_TRUE(message.command().has_stop()) << message.command().ShortDebugString();
  task = testing::FetchTask(*operator_, *task_id);
  ASSERT_TRUE(task.ok());
  EXPECT_EQ(task->status(), api::TASK_STATUS_SUCCEEDED);
  session->WritesDone();
  session_context.TryCancel();
}

// A complex instruction goes to the model path; the offline proxy answers the decompose task
// by rules (issue 15), so the task runs on the model's subgoals with no vendor and the event
// log says so.
TEST_F(GatewayModelContractTest, ComplexInstructionRunsOnTheOfflineProxysSubgoals) {
  const absl::StatusOr<std::string> task_id =
      testing::Submit(*operator_, "complex-1", "r2", "go to the kitchen and then find the clock");
  ASSERT_TRUE(task_id.ok()) << task_id.status();
  // Replay from event 1: TASK_CREATED is at least event 1, so the decomposition event comes after
  // it whether it is already logged (replayed) or not yet (live).
  grpc::ClientContext events_context;
  events_context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(20));
  api::StreamEventsRequest watch;
  watch.set_robot_id("r2");
  watch.set_last_event_id(1);
  auto events = operator_->StreamEvents(&events_context, watch);
  api::StreamEventsResponse event;
  std::string decomposition;
  while (decomposition.empty() && events->Read(&event)) {
    if (event.event().kind() == api::EVENT_KIND_DECOMPOSITION)
      decomposition = event.event().message();
  }
  EXPECT_EQ(event.event().task_id(), *task_id);
  EXPECT_EQ(decomposition, "model subgoals used: NAVIGATE(kitchen) FIND(clock)");

  const absl::StatusOr<api::TaskSnapshot> task = testing::FetchTask(*operator_, *task_id);
  ASSERT_TRUE(task.ok()) << task.status();
  EXPECT_EQ(task->decomposition_source(), "model");
  ASSERT_GE(task->subgoals_size(), 2);
  EXPECT_EQ(task->subgoals(0).type(), api::SUBGOAL_TYPE_NAVIGATE);  // kitchen
  EXPECT_EQ(task->subgoals(1).type(), api::SUBGOAL_TYPE_FIND);      // clock
  EXPECT_GE(task->model_calls(), 1);                                // the decompose call is counted
  events_context.TryCancel();
}

}  // namespace
}  // namespace semnav::reasoning
