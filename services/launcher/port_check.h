#pragma once

#include <string>

#include "absl/status/status.h"

namespace semnav::launcher {

// OK when a server could listen on `host:port` now. gRPC servers set SO_REUSEPORT, so a second
// stack on the same ports would otherwise start beside the first and split its clients.
// FAILED_PRECONDITION when something already listens there; an unresolvable host is left to the
// service to report.
absl::Status CheckListenAddressFree(const std::string& listen);

}  // namespace semnav::launcher
