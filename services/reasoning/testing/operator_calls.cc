#include "services/reasoning/testing/operator_calls.h"

#include <grpcpp/client_context.h>

#include <chrono>
#include <thread>

#include "absl/strings/str_cat.h"

namespace semnav::reasoning::testing {

absl::StatusOr<std::string> Submit(v1::OperatorService::Stub& stub, const std::string& request_id,
                                   const std::string& robot_id, const std::string& instruction) {
  v1::SubmitInstructionRequest request;
  request.set_request_id(request_id);
  request.set_robot_id(robot_id);
  request.set_instruction(instruction);
  v1::SubmitInstructionResponse response;
  grpc::ClientContext context;
  const grpc::Status status = stub.SubmitInstruction(&context, request, &response);
  if (!status.ok())
    return absl::UnknownError(absl::StrCat("SubmitInstruction: ", status.error_message()));
  return response.task_id();
}

bool WaitUntilPoseSeen(v1::OperatorService::Stub& stub, const std::string& robot_id,
                       int timeout_ms) {
  v1::StreamSlowTelemetryRequest request;
  request.set_robot_id(robot_id);
  request.mutable_period()->set_nanos(100'000'000);
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::milliseconds(timeout_ms));
  auto stream = stub.StreamSlowTelemetry(&context, request);
  v1::StreamSlowTelemetryResponse sample;
  while (stream->Read(&sample)) {
    if (sample.topological_nodes() > 0) {
      context.TryCancel();
      return true;
    }
  }
  return false;
}

v1::ConnectRequest PoseReport(double x, double y) {
  v1::ConnectRequest state;
  state.mutable_state()->mutable_pose()->mutable_position()->set_x(x);
  state.mutable_state()->mutable_pose()->mutable_position()->set_y(y);
  state.mutable_state()->mutable_pose()->mutable_orientation()->set_w(1.0);
  return state;
}

absl::StatusOr<v1::TaskSnapshot> FetchTask(v1::OperatorService::Stub& stub,
                                           const std::string& task_id) {
  v1::GetTaskRequest request;
  request.set_task_id(task_id);
  v1::GetTaskResponse response;
  grpc::ClientContext context;
  const grpc::Status status = stub.GetTask(&context, request, &response);
  if (!status.ok()) return absl::UnknownError(absl::StrCat("GetTask: ", status.error_message()));
  return response.task();
}

bool WaitUntilFastResolvable(v1::OperatorService::Stub& stub, const std::string& robot_id,
                             const std::string& text, int timeout_ms) {
  for (int waited = 0; waited <= timeout_ms; waited += 25) {
    v1::ResolveTargetRequest request;
    request.set_robot_id(robot_id);
    request.set_text(text);
    v1::ResolveTargetResponse response;
    grpc::ClientContext context;
    if (stub.ResolveTarget(&context, request, &response).ok() && response.has_target()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  return false;
}

}  // namespace semnav::reasoning::testing
