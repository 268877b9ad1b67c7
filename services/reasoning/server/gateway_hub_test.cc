// The hub without gRPC: a fake session sink records the robot commands.
#include "services/reasoning/server/gateway_hub.h"

#include "gtest/gtest.h"
#include "services/reasoning/server/hub_test_support.h"
#include "services/reasoning/server/robot_local_planner.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

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
  hub.OnRobotState(&session, At(0, 0));   // node 1 sees the sofa (1.1 m away)
  hub.OnRobotState(&session, At(6, 0));   // node 2, 5 m from the sofa: not seen
  hub.OnRobotState(&session, At(12, 0));  // node 3

  api::SubmitInstructionRequest request;
  request.set_request_id("back-1");
  request.set_robot_id("r1");
  request.set_instruction("回到沙发那里");
  absl::StatusOr<api::SubmitInstructionResponse> response = hub.Submit(request);
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

}  // namespace
}  // namespace semnav::reasoning
