// The robot's side of RobotSessionService/Connect: hello, state and feedback out; commands in
// (read by a background thread so the simulation never blocks on the gateway).
#pragma once

#include <grpcpp/grpcpp.h>

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "semnav/reasoning/v1/robot_session.grpc.pb.h"

namespace semnav::sim::loop {

// A command with the wall time the reader thread took it off the stream, for latency figures.
struct ReceivedCommand {
  semnav::reasoning::v1::RobotCommand command;
  absl::Time received_at;
};

class RobotSession {
 public:
  // Opens the stream and waits for SessionAccepted (or the gateway's refusal).
  static absl::StatusOr<std::unique_ptr<RobotSession>> Open(
      const std::shared_ptr<grpc::Channel>& gateway,
      const semnav::reasoning::v1::SessionHello& hello);
  ~RobotSession();

  absl::Status Send(const semnav::reasoning::v1::ConnectRequest& request);
  // Commands received since the last call, oldest first; waits up to `wait` for the first.
  std::vector<semnav::reasoning::v1::RobotCommand> TakeCommands(absl::Duration wait);
  std::vector<ReceivedCommand> TakeReceivedCommands(absl::Duration wait);
  // Simulated clock (lock step): waits until the gateway's StepDone for `step` and returns the
  // commands that came before it, oldest first. DEADLINE_EXCEEDED after `timeout` of wall time,
  // UNAVAILABLE when the stream ended first.
  absl::StatusOr<std::vector<semnav::reasoning::v1::RobotCommand>> TakeStepCommands(
      uint64_t step, absl::Duration timeout);
  // True once the gateway ended the stream (or it broke).
  bool closed();
  // The gateway's latest LocalizationUpdate since the last call (lock step: those sent before the
  // last StepDone); nullopt when none came.
  std::optional<semnav::reasoning::v1::LocalizationUpdate> TakeLocalization();

 private:
  RobotSession() = default;
  void ReadLoop();

  grpc::ClientContext context_;
  std::unique_ptr<semnav::reasoning::v1::RobotSessionService::Stub> stub_;
  std::unique_ptr<grpc::ClientReaderWriter<semnav::reasoning::v1::ConnectRequest,
                                           semnav::reasoning::v1::ConnectResponse>>
      stream_;
  std::thread reader_;
  absl::Mutex mu_;
  std::deque<ReceivedCommand> commands_ ABSL_GUARDED_BY(mu_);
  bool step_done_ ABSL_GUARDED_BY(mu_) = false;  // a StepDone came
  uint64_t last_step_done_ ABSL_GUARDED_BY(mu_) = 0;
  std::size_t commands_before_done_ ABSL_GUARDED_BY(mu_) = 0;  // leading commands_ sent before it
  bool closed_ ABSL_GUARDED_BY(mu_) = false;
  std::optional<semnav::reasoning::v1::LocalizationUpdate> localization_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::sim::loop
