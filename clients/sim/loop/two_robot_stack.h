// The services of the two-robot scenario: one relocalization service and one mapping service per
// robot (a mapping service holds one live map), each mapping pushing its landmarks to
// relocalization (mapping.landmarks.relocalization). Started with the launcher's StackRunner
// from a bin folder on free loopback ports.
#pragma once

#include <grpcpp/channel.h>

#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "services/launcher/stack_runner.h"

namespace semnav::sim::loop {

struct TwoRobotEndpoints {
  std::shared_ptr<grpc::Channel> mapping_a;
  std::shared_ptr<grpc::Channel> mapping_b;
  std::shared_ptr<grpc::Channel> relocalization;
};

class TwoRobotStack {
 public:
  // `work_dir` gets the configs and both mapping stores (created).
  static absl::StatusOr<std::unique_ptr<TwoRobotStack>> Start(const std::string& bin_dir,
                                                              const std::string& work_dir);
  ~TwoRobotStack();
  TwoRobotEndpoints endpoints() const;

 private:
  TwoRobotStack() = default;
  std::unique_ptr<semnav::launcher::StackRunner> runner_;
  std::string mapping_a_, mapping_b_, relocalization_;
};

}  // namespace semnav::sim::loop
