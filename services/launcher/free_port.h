#pragma once

#include "absl/status/statusor.h"

namespace semnav::launcher {

// A loopback TCP port the kernel reports free right now. Another process may still take it
// before a service binds; that service's start then fails loudly.
absl::StatusOr<int> FreeLoopbackPort();

}  // namespace semnav::launcher
