// The relocalization loop's contract through the real binaries on loopback: semnav-gateway with
// semnav-relocalization configured, a scripted robot on the session stream. A robot that reports
// LOST (RobotState.localization) gets its task paused, a look-around and the gateway's
// relocalizing flag; with nothing to relocalize on, the task fails with the reason. The operator's
// RelocalizeRobot starts the same loop, answers idempotently and names its errors' fields.
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <memory>
#include <optional>
#include <thread>

#include "absl/strings/match.h"
#include "gtest/gtest.h"
#include "semnav/common/v1/errors.pb.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "semnav/reasoning/v1/robot_session.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "services/reasoning/testing/operator_calls.h"
#include "services/reasoning/testing/service_stack.h"
#include "tests/support/service_process.h"

namespace semnav::testing {
namespace {

namespace api = ::semnav::reasoning::v1;
namespace rt = ::semnav::reasoning::testing;

using Stream = grpc::ClientReaderWriter<api::ConnectRequest, api::ConnectResponse>;

// A robot on the session stream: hello, states, and a reader of the gateway's messages.
class Robot {
 public:
  Robot(const std::shared_ptr<grpc::Channel>& channel, const std::string& robot_id)
      : stub_(api::RobotSessionService::NewStub(channel)) {
    context_.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(60));
    stream_ = stub_->Connect(&context_);
    api::ConnectRequest hello;
    hello.mutable_hello()->set_robot_id(robot_id);
    EXPECT_TRUE(stream_->Write(hello));
    api::ConnectResponse accepted;
    EXPECT_TRUE(stream_->Read(&accepted));
    EXPECT_TRUE(accepted.has_accepted());
  }
  ~Robot() {
    if (finished_) return;
    stream_->WritesDone();
    context_.TryCancel();
    stream_->Finish();
  }
  bool State(double x, double y, api::LocalizationStatus status) {
    api::ConnectRequest report = rt::PoseReport(x, y);
    report.mutable_state()->set_localization(status);
    return stream_->Write(report);
  }
  // Reads until a message satisfies `match` (messages before it are dropped); nullopt when the
  // stream ends first.
  template <typename Match>
  std::optional<api::ConnectResponse> ReadUntil(Match match) {
    api::ConnectResponse message;
    while (stream_->Read(&message)) {
      if (match(message)) return message;
    }
    return std::nullopt;
  }
  grpc::Status Finish() {
    finished_ = true;
    stream_->WritesDone();
    return stream_->Finish();
  }

 private:
  std::unique_ptr<api::RobotSessionService::Stub> stub_;
  grpc::ClientContext context_;
  std::unique_ptr<Stream> stream_;
  bool finished_ = false;
};

// The loop's look-around (the task's own LOOK_AROUND turns say otherwise).
bool IsRotate(const api::ConnectResponse& m) {
  return m.has_command() && m.command().has_rotate() &&
         absl::StartsWith(m.command().reason(), "relocalizing");
}

std::vector<api::Event> Events(api::OperatorService::Stub& op, const std::string& robot_id) {
  api::ListEventsRequest request;
  request.set_robot_id(robot_id);
  api::ListEventsResponse response;
  grpc::ClientContext context;
  EXPECT_TRUE(op.ListEvents(&context, request, &response).ok());
  return {response.events().begin(), response.events().end()};
}

std::optional<api::Event> FindEvent(api::OperatorService::Stub& op, const std::string& robot_id,
                                    api::EventKind kind) {
  for (const api::Event& event : Events(op, robot_id)) {
    if (event.kind() == kind) return event;
  }
  return std::nullopt;
}

class RelocalizationLoopContractTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = rt::FreshDir("relocalization_loop_contract");
    auto reloc = rt::StartWithConfig("semnav-relocalization", dir_, "reloc.yaml",
                                     "relocalization:\n  storage_dir: " + dir_ + "/landmarks\n");
    ASSERT_TRUE(reloc.ok()) << reloc.status();
    reloc_ = *std::move(reloc);
    // A short look-around keeps the wall-clock test short; one attempt.
    auto gateway =
        rt::StartWithConfig("semnav-gateway", dir_, "gateway.yaml",
                            "gateway:\n  relocalization:\n    address: " + reloc_->address() +
                                "\n    look_around_duration_s: 0.3\n    max_attempts: 1\n");
    ASSERT_TRUE(gateway.ok()) << gateway.status();
    gateway_ = *std::move(gateway);
    operator_ = api::OperatorService::NewStub(gateway_->channel());
  }

  grpc::Status Relocalize(const std::string& request_id, const std::string& robot_id,
                          api::RelocalizeRobotResponse* response, const std::string& reason = "") {
    api::RelocalizeRobotRequest request;
    request.set_request_id(request_id);
    request.set_robot_id(robot_id);
    request.set_reason(reason);
    grpc::ClientContext context;
    return operator_->RelocalizeRobot(&context, request, response);
  }

  std::string dir_;
  std::unique_ptr<ServiceProcess> reloc_;
  std::unique_ptr<ServiceProcess> gateway_;
  std::unique_ptr<api::OperatorService::Stub> operator_;
};

TEST_F(RelocalizationLoopContractTest, LostReportPausesTheTaskLooksAroundAndFailsItWithoutObjects) {
  Robot robot(gateway_->channel(), "r1");
  ASSERT_TRUE(robot.State(1.0, 1.0, api::LOCALIZATION_STATUS_OK));
  ASSERT_TRUE(rt::WaitUntilPoseSeen(*operator_, "r1", 5000));
  const absl::StatusOr<std::string> task_id =
      rt::Submit(*operator_, "find-chair", "r1", "find the chair");
  ASSERT_TRUE(task_id.ok()) << task_id.status();
  ASSERT_TRUE(
      robot.ReadUntil([](const api::ConnectResponse& m) { return m.has_command(); }).has_value());

  ASSERT_TRUE(robot.State(1.0, 1.0, api::LOCALIZATION_STATUS_LOST));
  // The look-around: rotate in place at the LOOK_AROUND rate, and the gateway's relocalizing flag.
  std::optional<api::ConnectResponse> rotate = robot.ReadUntil(IsRotate);
  ASSERT_TRUE(rotate.has_value());
  EXPECT_DOUBLE_EQ(rotate->command().rotate().angular_speed_rps(), 0.75);  // the default rate
  EXPECT_DOUBLE_EQ(rotate->command().rotate().duration_s(), 0.3);
  std::optional<api::ConnectResponse> update =
      robot.ReadUntil([](const api::ConnectResponse& m) { return m.has_localization(); });
  ASSERT_TRUE(update.has_value());
  EXPECT_TRUE(update->localization().relocalizing());
  absl::StatusOr<api::TaskSnapshot> paused = rt::FetchTask(*operator_, *task_id);
  ASSERT_TRUE(paused.ok());
  EXPECT_EQ(paused->status(), api::TASK_STATUS_PAUSED);
  std::optional<api::Event> relocalizing =
      FindEvent(*operator_, "r1", api::EVENT_KIND_RELOCALIZING);
  ASSERT_TRUE(relocalizing.has_value());
  EXPECT_TRUE(absl::StrContains(relocalizing->message(), "robot reports LOST"))
      << relocalizing->message();
  EXPECT_EQ(relocalizing->task_id(), *task_id);

  // The turn ends with no scene graph (no mapping): nothing to relocalize on, the task fails.
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  ASSERT_TRUE(robot.State(1.0, 1.0, api::LOCALIZATION_STATUS_LOST));
  std::optional<api::ConnectResponse> stop = robot.ReadUntil(
      [](const api::ConnectResponse& m) { return m.has_command() && m.command().has_stop(); });
  ASSERT_TRUE(stop.has_value());
  absl::StatusOr<api::TaskSnapshot> failed = rt::FetchTask(*operator_, *task_id);
  ASSERT_TRUE(failed.ok());
  EXPECT_EQ(failed->status(), api::TASK_STATUS_FAILED);
  EXPECT_TRUE(absl::StrContains(failed->reason(), "relocalization failed")) << failed->reason();
  EXPECT_TRUE(absl::StrContains(failed->reason(), "saw 0 objects")) << failed->reason();
  EXPECT_TRUE(FindEvent(*operator_, "r1", api::EVENT_KIND_RELOCALIZATION_FAILED).has_value());
  // The gateway no longer trusts the pose: telemetry says so.
  api::RelocalizeRobotResponse status;
  ASSERT_TRUE(Relocalize("again-1", "r1", &status).ok());
  EXPECT_EQ(status.localization().failures(), 1u);
  EXPECT_EQ(status.localization().reported(), api::LOCALIZATION_STATUS_LOST);
}

TEST_F(RelocalizationLoopContractTest, RelocalizeRobotStartsTheLoopIdempotentlyAndNamesItsErrors) {
  api::RelocalizeRobotResponse response;
  grpc::Status unknown = Relocalize("req-1", "nobody", &response);
  EXPECT_EQ(unknown.error_code(), grpc::StatusCode::NOT_FOUND);
  ASSERT_TRUE(GetDetail<common::v1::ErrorInfo>(unknown).has_value());
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(unknown)->field(), "robot_id");
  grpc::Status missing = Relocalize("", "r2", &response);
  EXPECT_EQ(missing.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(missing)->field(), "request_id");

  Robot robot(gateway_->channel(), "r2");
  ASSERT_TRUE(
      robot.State(2.0, 0.0, api::LOCALIZATION_STATUS_UNSPECIFIED));  // an old robot: read as OK
  ASSERT_TRUE(rt::WaitUntilPoseSeen(*operator_, "r2", 5000));
  ASSERT_TRUE(Relocalize("req-2", "r2", &response, "drill").ok());
  EXPECT_TRUE(response.localization().relocalizing());
  EXPECT_TRUE(response.localization().trusted());
  EXPECT_EQ(response.localization().trigger(), "operator request: drill");
  EXPECT_NEAR(response.localization().map_pose().position().x(), 2.0, 1e-9);
  EXPECT_TRUE(robot.ReadUntil(IsRotate).has_value());
  api::RelocalizeRobotResponse again;
  ASSERT_TRUE(Relocalize("req-2", "r2", &again, "other").ok());
  EXPECT_EQ(again.SerializeAsString(), response.SerializeAsString());

  // A gateway without relocalization refuses, naming the robot and the reason.
  auto plain = rt::StartWithConfig("semnav-gateway", dir_, "plain.yaml", "gateway: {}\n");
  ASSERT_TRUE(plain.ok()) << plain.status();
  Robot other((*plain)->channel(), "r3");
  ASSERT_TRUE(other.State(0.0, 0.0, api::LOCALIZATION_STATUS_LOST));
  auto plain_operator = api::OperatorService::NewStub((*plain)->channel());
  ASSERT_TRUE(rt::WaitUntilPoseSeen(*plain_operator, "r3", 5000));
  api::RelocalizeRobotRequest request;
  request.set_request_id("req-3");
  request.set_robot_id("r3");
  grpc::ClientContext context;
  grpc::Status refused = plain_operator->RelocalizeRobot(&context, request, &response);
  EXPECT_EQ(refused.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(refused)->field(), "robot_id");
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(refused)->reason(), "RELOCALIZATION_UNAVAILABLE");
}

TEST_F(RelocalizationLoopContractTest, UnknownLocalizationStatusEndsTheStreamNamingTheField) {
  Robot robot(gateway_->channel(), "r4");
  ASSERT_TRUE(robot.State(0.0, 0.0, static_cast<api::LocalizationStatus>(42)));
  const grpc::Status status = robot.Finish();
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  ASSERT_TRUE(GetDetail<common::v1::ErrorInfo>(status).has_value());
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(status)->field(), "state.localization");
}

}  // namespace
}  // namespace semnav::testing
