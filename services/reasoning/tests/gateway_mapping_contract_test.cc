// End-to-end contract: real semnav-mapping fed with synthetic RGB-D frames carrying a "table"
// detection, real semnav-gateway following its scene graph, a scripted robot on the session
// stream. "go to the table" must run NAVIGATE -> APPROACH -> VERIFY (confirmed by new detections)
// and end with a STOP within 1 m of the table.
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <thread>

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
using testing::kTableCentre;

std::chrono::system_clock::time_point Deadline() {
  return std::chrono::system_clock::now() + std::chrono::seconds(30);
}

class GatewayMappingContractTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string dir = testing::FreshDir("gateway_mapping_contract");
    auto mapping = testing::StartMapping(dir);
    ASSERT_TRUE(mapping.ok()) << mapping.status();
    mapping_ = *std::move(mapping);
    auto gateway = testing::StartWithConfig(
        "semnav-gateway", dir, "gateway.yaml",
        "gateway:\n  mapping:\n    address: " + mapping_->address() + "\n");
    ASSERT_TRUE(gateway.ok()) << gateway.status();
    gateway_ = *std::move(gateway);
    operator_ = api::OperatorService::NewStub(gateway_->channel());
  }

  void StreamFrames(int count) {
    ASSERT_TRUE(testing::StreamTableFrames(mapping_->channel(), frames_ + 1, count).ok());
    frames_ += count;
  }

  api::TaskSnapshot Task(const std::string& task_id) {
    absl::StatusOr<api::TaskSnapshot> task = testing::FetchTask(*operator_, task_id);
    EXPECT_TRUE(task.ok()) << task.status();
    return task.ok() ? *task : api::TaskSnapshot();
  }
  Eigen::Vector2d TargetOf(const std::string& task_id) {
    const api::TaskSnapshot task = Task(task_id);
    return Eigen::Vector2d(task.target().position().x(), task.target().position().y());
  }

  std::unique_ptr<semnav::testing::ServiceProcess> mapping_;
  std::unique_ptr<semnav::testing::ServiceProcess> gateway_;
  std::unique_ptr<api::OperatorService::Stub> operator_;
  int64_t frames_ = 0;
};

TEST_F(GatewayMappingContractTest, GoToTheTableEndsStoppedWithinOneMetre) {
  StreamFrames(6);  // 6 observations at score 0.9: fused 0.35 + 0.35 + 0.15 * 0.9 * 0.6 = 0.781
  ASSERT_TRUE(testing::WaitUntilFastResolvable(*operator_, "r1", "go to the table", 5000));

  auto session_stub = api::RobotSessionService::NewStub(gateway_->channel());
  grpc::ClientContext session_context;
  session_context.set_deadline(Deadline());
  auto session = session_stub->Connect(&session_context);
  api::ConnectRequest hello;
  hello.mutable_hello()->set_robot_id("r1");
  ASSERT_TRUE(session->Write(hello));
  api::ConnectResponse message;
  ASSERT_TRUE(session->Read(&message));
  ASSERT_TRUE(message.has_accepted());
  auto report = [&](const api::RobotCommand* done, double x, double y) {
    ASSERT_TRUE(session->Write(testing::PoseReport(x, y)));
    if (done == nullptr) return;
    api::ConnectRequest feedback;
    feedback.mutable_feedback()->set_command_id(done->command_id());
    feedback.mutable_feedback()->set_kind(api::FEEDBACK_KIND_GOAL_REACHED);
    ASSERT_TRUE(session->Write(feedback));
  };
  report(nullptr, 0.5, 2.0);

  const absl::StatusOr<std::string> task_id =
      testing::Submit(*operator_, "go-table", "r1", "go to the table");
  ASSERT_TRUE(task_id.ok()) << task_id.status();

  // NAVIGATE: 1 m short of the table, facing it.
  ASSERT_TRUE(session->Read(&message));
  const api::RobotCommand navigate = message.command();
  ASSERT_TRUE(navigate.has_navigate()) << navigate.ShortDebugString();
  const Eigen::Vector2d goal(navigate.navigate().goal().x(), navigate.navigate().goal().y());
  const Eigen::Vector2d mapped = TargetOf(*task_id);  // mapping's estimate of the table
  EXPECT_NEAR((goal - mapped).norm(), 1.0, 1e-6);
  EXPECT_LT((mapped - kTableCentre.head<2>()).norm(), 0.5);
  report(&navigate, goal.x(), goal.y());

  // APPROACH: 0.5 m from the table at 0.15 m/s.
  ASSERT_TRUE(session->Read(&message));
  const api::RobotCommand approach = message.command();
  ASSERT_TRUE(approach.has_navigate()) << approach.ShortDebugString();
  EXPECT_DOUBLE_EQ(approach.navigate().max_speed_mps(), 0.15);
  const Eigen::Vector2d close(approach.navigate().goal().x(), approach.navigate().goal().y());
  report(&approach, close.x(), close.y());

  // VERIFY: turn in place; two new detections from mapping confirm the table.
  ASSERT_TRUE(session->Read(&message));
  const api::RobotCommand verify = message.command();
  ASSERT_TRUE(verify.has_navigate()) << verify.ShortDebugString();
  EXPECT_NEAR(verify.navigate().goal().x(), close.x(), 1e-9);
  report(&verify, close.x(), close.y());
  ASSERT_TRUE(session->Read(&message));  // facing it: hold while detections confirm it
  EXPECT_TRUE(message.command().has_hold()) << message.command().ShortDebugString();
  StreamFrames(2);
  ASSERT_TRUE(session->Read(&message));
  EXPECT_TRUE(message.command().has_stop()) << message.command().ShortDebugString();

  const api::TaskSnapshot task = Task(*task_id);
  EXPECT_EQ(task.status(), api::TASK_STATUS_SUCCEEDED);
  EXPECT_EQ(task.target().path(), api::RESOLUTION_PATH_FAST);
  EXPECT_LE((close - TargetOf(*task_id)).norm(), 1.0);  // seed 004 success radius
  session->WritesDone();
  session_context.TryCancel();
}

}  // namespace
}  // namespace semnav::reasoning
