#include "services/reasoning/bench/loopback_latency.h"

#include <grpcpp/grpcpp.h>

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "semnav/reasoning/v1/robot_session.grpc.pb.h"
#include "services/reasoning/testing/operator_calls.h"
#include "services/reasoning/testing/table_scene_frames.h"
#include "tests/support/service_process.h"

namespace semnav::reasoning {
namespace {

namespace api = ::semnav::reasoning::v1;

const Eigen::Vector3d kClock(6.0, 1.3, 1.0);  // on the far wall, behind the table
constexpr double kRobotX = 1.5;               // the robot faces the table from this side
constexpr double kRobotY = 1.3;

}  // namespace

absl::StatusOr<LoopbackLatency> MeasureInstructionToCommand(int samples, bool with_model_proxy) {
  const std::string dir =
      (std::filesystem::temp_directory_path() /
       (with_model_proxy ? "semnav-bench-gateway-model" : "semnav-bench-gateway"))
          .string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/mapping.yaml") << "mapping:\n  store_directory: " << dir << "/maps\n"
                                       << "  watch_min_interval_ms: 20\n";
  absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> mapping =
      semnav::testing::ServiceProcess::Start("semnav-mapping", {"--config", dir + "/mapping.yaml"});
  if (!mapping.ok()) return mapping.status();
  if (absl::Status s = testing::StreamLabelledFrames((*mapping)->channel(), 1, 6, "clock", kClock);
      !s.ok())
    return s;
  std::ofstream(dir + "/planning.yaml")
      << "planning:\n  mapping:\n    address: " << (*mapping)->address() << "\n";
  absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> planning =
      semnav::testing::ServiceProcess::Start("semnav-planning",
                                             {"--config", dir + "/planning.yaml"});
  if (!planning.ok()) return planning.status();
  // With the model configured: the real semnav-model-proxy with its default (offline) chain,
  // as `semnav up` runs it; every task then also asks it for the target's text embedding.
  std::unique_ptr<semnav::testing::ServiceProcess> proxy;
  if (with_model_proxy) {
    absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> started =
        semnav::testing::ServiceProcess::Start("semnav-model-proxy", {});
    if (!started.ok()) return started.status();
    proxy = *std::move(started);
  }
  std::ofstream(dir + "/gateway.yaml")
      << "gateway:\n  mapping:\n    address: " << (*mapping)->address()
      << "\n  planning:\n    address: " << (*planning)->address() << "\n"
      << (proxy != nullptr ? absl::StrCat("  model_proxy:\n    address: ", proxy->address(), "\n")
                           : "");
  absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> gateway =
      semnav::testing::ServiceProcess::Start("semnav-gateway", {"--config", dir + "/gateway.yaml"});
  if (!gateway.ok()) return gateway.status();
  auto operator_stub = api::OperatorService::NewStub((*gateway)->channel());
  if (!testing::WaitUntilFastResolvable(*operator_stub, "bench", "go to the clock", 5000)) {
    return absl::DeadlineExceededError("gateway never resolved the clock");
  }

  auto session_stub = api::RobotSessionService::NewStub((*gateway)->channel());
  grpc::ClientContext session_context;
  auto session = session_stub->Connect(&session_context);
  api::ConnectRequest hello;
  hello.mutable_hello()->set_robot_id("bench");
  api::ConnectResponse message;
  if (!session->Write(hello) || !session->Read(&message))
    return absl::InternalError("session did not open");
  if (!session->Write(testing::PoseReport(kRobotX, kRobotY)))
    return absl::InternalError("session closed");
  if (!testing::WaitUntilPoseSeen(*operator_stub, "bench", 5000))
    return absl::DeadlineExceededError("pose never seen");

  LoopbackLatency latency;
  std::vector<double> millis;
  for (int i = 0; i < samples; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const absl::StatusOr<std::string> task_id =
        testing::Submit(*operator_stub, absl::StrCat("bench-", i), "bench", "go to the clock");
    if (!task_id.ok()) return task_id.status();
    // The previous task's STOP comes first; the new task's NAVIGATE ends the sample.
    do {
      if (!session->Read(&message)) return absl::InternalError("session ended");
    } while (!(message.has_command() && message.command().has_navigate() &&
               message.command().task_id() == *task_id));
    millis.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    if (message.command().navigate().path_size() > 0) ++latency.planned;
  }
  session_context.TryCancel();
  std::sort(millis.begin(), millis.end());
  latency.samples = samples;
  latency.p50_ms = millis[millis.size() / 2];
  latency.p99_ms = millis[static_cast<std::size_t>(0.99 * (millis.size() - 1))];
  return latency;
}

}  // namespace semnav::reasoning
