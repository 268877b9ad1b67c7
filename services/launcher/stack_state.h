#pragma once

#include <sys/types.h>

#include <map>
#include <optional>
#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "services/launcher/stack_config.h"

namespace semnav::launcher {

// What a running `semnav up` publishes for `semnav status`: its pid and, per child, how often it
// was restarted and why it last exited.
struct ChildState {
  pid_t pid = -1;
  int restarts = 0;
  std::string last_exit;  // "" while it never exited
};

struct StackState {
  pid_t launcher_pid = -1;
  std::string dashboard_url;
  std::map<std::string, ChildState> children;  // by child name
};

// Files of one stack, keyed by its listen addresses, in the temp folder: the state (JSON,
// replaced atomically) and the lock that keeps a second `semnav up` of it from starting.
std::string StackStatePath(const StackConfig& config);
std::string StackLockPath(const StackConfig& config);

absl::Status WriteStackState(const std::string& path, const StackState& state);
// NOT_FOUND when absent, or when the launcher that wrote it is gone.
absl::StatusOr<StackState> ReadLiveStackState(const std::string& path);

// Holds an exclusive lock on `path` for its lifetime. FAILED_PRECONDITION names the holder's
// pid when another process has it.
class StackLock {
 public:
  static absl::StatusOr<StackLock> Acquire(const std::string& path);
  StackLock(StackLock&& other) noexcept;
  StackLock& operator=(StackLock&&) = delete;
  ~StackLock();

 private:
  explicit StackLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace semnav::launcher
