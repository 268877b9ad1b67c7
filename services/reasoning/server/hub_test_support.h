// Test helpers for GatewayHub tests: a robot-session sink that records what the hub sends, and
// robot states.
#pragma once

#include <optional>
#include <vector>

#include "absl/synchronization/mutex.h"
#include "services/reasoning/server/gateway_hub.h"

namespace semnav::reasoning {

// Thread-safe: model answers arrive on other threads.
class RecordingSink : public StreamSink<api::ConnectResponse> {
 public:
  void Send(const api::ConnectResponse& message) override {
    absl::MutexLock lock(&mu_);
    messages_.push_back(message);
  }
  void Close(const grpc::Status& status) override {
    absl::MutexLock lock(&mu_);
    closed_ = status;
  }
  std::vector<api::ConnectResponse> messages() {
    absl::MutexLock lock(&mu_);
    return messages_;
  }
  api::RobotCommand Last() {
    absl::MutexLock lock(&mu_);
    return messages_.back().command();
  }
  std::optional<grpc::Status> closed() {
    absl::MutexLock lock(&mu_);
    return closed_;
  }

 private:
  absl::Mutex mu_;
  std::vector<api::ConnectResponse> messages_;
  std::optional<grpc::Status> closed_;
};

inline api::RobotState At(double x, double y) {
  api::RobotState state;
  state.mutable_pose()->mutable_position()->set_x(x);
  state.mutable_pose()->mutable_position()->set_y(y);
  state.mutable_pose()->mutable_orientation()->set_w(1.0);
  return state;
}

}  // namespace semnav::reasoning
