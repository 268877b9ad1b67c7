#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "services/launcher/stack_config.h"

namespace semnav::launcher {

// Starts every service of a stack as a child process, waits for health SERVING, and stops
// them all (SIGTERM, then SIGKILL after stop_timeout_s).
class StackRunner {
 public:
  StackRunner(StackConfig config, std::string bin_dir);
  ~StackRunner();

  // Starts all services; on any failure, stops those already started.
  absl::Status Start();
  // Blocks until SIGINT/SIGTERM (returns OK) or a service exits by itself (returns the error).
  absl::Status WaitForStopRequest();
  // Stops every running service; OK if all exited with code 0.
  absl::Status Stop();

 private:
  struct Child {
    StackService service;
    pid_t pid = -1;
  };
  StackConfig config_;
  std::string bin_dir_;
  std::vector<Child> children_;
};

// Health of every service of the stack, one line each; OK if all are SERVING.
absl::Status PrintStatus(const StackConfig& config);

}  // namespace semnav::launcher
