// Test helpers for GatewayHub tests: a robot-session sink that records what the hub sends, robot
// states and the scenes several tests share.
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

// One sofa at (1.0, 0.5), scene-graph revision 1 (the backtrack tests' "where the sofa was seen").
inline SceneGraph SofaScene() {
  SceneGraph graph;
  graph.revision = 1;
  SceneObject sofa;
  sofa.id = 5;
  sofa.label = "sofa";
  sofa.position = Eigen::Vector3d(1.0, 0.5, 0.4);
  graph.objects.push_back(sofa);
  return graph;
}

// A cup without a colour: "red cup" scores label 0.5 (colour unknown), embedding 0.5 (fallback),
// detector 0.9, spatial 0: fused 0.175 + 0.175 + 0.135 = 0.485 <= 0.75, so the slow path runs.
inline SceneGraph CupScene() {
  SceneGraph graph;
  graph.revision = 3;
  SceneObject cup;
  cup.id = 7;
  cup.label = "cup";
  cup.position = Eigen::Vector3d(4.0, 0.0, 0.8);
  cup.score = 0.9;
  cup.detection_count = 10;
  graph.objects.push_back(cup);
  return graph;
}

}  // namespace semnav::reasoning
