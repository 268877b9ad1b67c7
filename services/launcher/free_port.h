#pragma once

#include "absl/status/statusor.h"

namespace semnav::launcher {

// A loopback TCP port free right now, picked at random below the kernel's ephemeral range (so
// no outgoing connection takes it meanwhile; the kernel's own pick when that range leaves no
// room). Another process may still take it before a service binds; that service's start then
// fails loudly.
absl::StatusOr<int> FreeLoopbackPort();

}  // namespace semnav::launcher
