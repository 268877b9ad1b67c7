// The hub without gRPC: a fake session sink records the robot commands.
#include "services/reasoning/server/gateway_hub.h"

#include "absl/strings/match.h"
#include "gtest/gtest.h"
#include "services/reasoning/server/hub_test_support.h"
#include "services/reasoning/server/robot_local_planner.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

api::SubmitInstructionRequest SubmitRequest(const std::string& request_id, const std::string& robot_id,
                                            const std::string& instruction) {
  api::SubmitInstructionRequest request;
  request.set_request_id(request_id);
  request.set_robot_id(robot_id);
  request.set_instruction(instruction);
  return request;
}

TEST(GatewayHubTest, BacktrackReturnsToWhereTheSofaWasSeen) {
  RobotLocalPlanner planner;
  const GatewayConfig config;
  GatewayHub hub(config, &ShippedLexicon(), &planner);
  SceneGraph graph;
  graph.revision = 1;
  SceneObject sofa;
  sofa.id = 5;
  sofa.label = "sofa";
  sofa.position = Eigen::Vector3d(1.0, 0.5, 0.4);
  graph.objects.push_back(sofa);
  hub.OnSceneGraph(graph);

  RecordingSink session;
  api::SessionHello hello;
  hello.set_robot_id("r1");
  ASSERT_TRUE(hub.OpenSession(hello, &session).ok());
  ASSERT_TRUE(hub.OnRobotState(&session, At(0, 0)).ok());   // node 1 sees the sofa (1.1 m away)
  ASSERT_TRUE(hub.OnRobotState(&session, At(6, 0)).ok());   // node 2, 5 m from the sofa: not seen
  ASSERT_TRUE(hub.OnRobotState(&session, At(12, 0)).ok());  // node 3

  absl::StatusOr<api::SubmitInstructionResponse> response = hub.Submit(SubmitRequest("back-1", "r1", "回到沙发那里"));
  ASSERT_TRUE(response.ok()) << response.status();
  ASSERT_EQ(response->task().subgoals(0).type(), api::SUBGOAL_TYPE_BACKTRACK);
  ASSERT_GE(session.messages().size(), 2u);  // accepted + navigate
  const api::RobotCommand command = session.Last();
  ASSERT_TRUE(command.has_navigate()) << command.ShortDebugString();
  EXPECT_DOUBLE_EQ(command.navigate().goal().x(), 0.0);
  EXPECT_DOUBLE_EQ(command.navigate().goal().y(), 0.0);
  EXPECT_EQ(command.navigate().path_size(), 0);  // no planning service: robot plans locally
  hub.Shutdown();
  ASSERT_TRUE(session.closed().has_value());
  EXPECT_EQ(session.closed()->error_code(), grpc::StatusCode::UNAVAILABLE);
}

// operator.proto: control of a finished task is FAILED_PRECONDITION naming task_id, but a retry
// of the call that finished it (same request_id) gets that call's answer again.
TEST(GatewayHubTest, ControlOfAFinishedTaskIsRefusedButARetryGetsTheFirstAnswer) {
  RobotLocalPlanner planner;
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner);
  absl::StatusOr<api::SubmitInstructionResponse> submitted = hub.Submit(SubmitRequest("s-1", "r1", "wait"));
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  api::CancelTaskRequest cancel;
  cancel.set_request_id("c-1");
  cancel.set_task_id(submitted->task_id());
  absl::StatusOr<api::TaskSnapshot> cancelled = hub.Cancel(cancel);
  ASSERT_TRUE(cancelled.ok()) << cancelled.status();
  EXPECT_EQ(cancelled->status(), api::TASK_STATUS_CANCELLED);

  absl::StatusOr<api::TaskSnapshot> retried = hub.Cancel(cancel);
  ASSERT_TRUE(retried.ok()) << retried.status();
  EXPECT_EQ(retried->SerializeAsString(), cancelled->SerializeAsString());

  cancel.set_request_id("c-2");
  const absl::Status again = hub.Cancel(cancel).status();
  EXPECT_EQ(again.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(again.message(), "task_id: task task-1 already finished (TASK_STATUS_CANCELLED)");
  api::PauseTaskRequest pause;
  pause.set_request_id("p-1");
  pause.set_task_id(submitted->task_id());
  EXPECT_EQ(hub.Pause(pause).status().code(), absl::StatusCode::kFailedPrecondition);
  api::ResumeTaskRequest resume;
  resume.set_request_id("r-1");
  resume.set_task_id(submitted->task_id());
  EXPECT_EQ(hub.Resume(resume).status().code(), absl::StatusCode::kFailedPrecondition);
}

TEST(GatewayHubTest, LeaseErrorsNameTheFieldOnce) {
  RobotLocalPlanner planner;
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner);
  api::AcquireLeaseRequest acquire;
  acquire.set_request_id("l-1");
  acquire.set_robot_id("r2");
  acquire.set_holder("alice");
  ASSERT_TRUE(hub.AcquireLease(acquire).ok());
  acquire.set_request_id("l-2");
  acquire.set_holder("bob");
  const absl::Status held = hub.AcquireLease(acquire).status();
  EXPECT_EQ(held.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_TRUE(absl::StartsWith(held.message(), "robot_id: lease of r2 is held by alice until ")) << held.message();

  const absl::Status refused = hub.Submit(SubmitRequest("s-1", "r2", "wait")).status();
  EXPECT_EQ(refused.message(), "lease_id: robot r2 is leased by alice");
}

}  // namespace
}  // namespace semnav::reasoning
