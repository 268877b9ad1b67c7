// Operator API calls and robot-session messages shared by the gateway's contract tests and
// benchmark.
#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "semnav/reasoning/v1/robot_session.pb.h"

namespace semnav::reasoning::testing {

// SubmitInstruction -> the new task id.
absl::StatusOr<std::string> Submit(v1::OperatorService::Stub& stub, const std::string& request_id,
                                   const std::string& robot_id, const std::string& instruction);

// True once the gateway has processed a pose of `robot_id` (its topological memory has a node),
// read from slow telemetry every 100 ms; false after `timeout_ms`.
bool WaitUntilPoseSeen(v1::OperatorService::Stub& stub, const std::string& robot_id,
                       int timeout_ms);

// A robot-session state message placing the robot at (x, y), heading +x.
v1::ConnectRequest PoseReport(double x, double y);

absl::StatusOr<v1::TaskSnapshot> FetchTask(v1::OperatorService::Stub& stub,
                                           const std::string& task_id);

// Polls ResolveTarget(text) every 25 ms until the fast path resolves it; false after `timeout_ms`.
bool WaitUntilFastResolvable(v1::OperatorService::Stub& stub, const std::string& robot_id,
                             const std::string& text, int timeout_ms);

}  // namespace semnav::reasoning::testing
