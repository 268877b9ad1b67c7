// Exit codes of semnavctl, one per outcome a script may want to branch on.
#pragma once

#include <string>

#include "absl/status/status.h"

namespace semnav::cli {

enum class ExitCode : int {
  kOk = 0,
  kError = 1,             // any other error (INTERNAL, UNKNOWN, DATA_LOSS, UNIMPLEMENTED, ...)
  kUsage = 2,             // bad command line: unknown command or flag, malformed value
  kUnavailable = 3,       // service unreachable or not serving (UNAVAILABLE)
  kDeadlineExceeded = 4,  // --deadline passed (DEADLINE_EXCEEDED)
  kNotFound = 5,          // NOT_FOUND: unknown task, lease, map, no path
  kInvalidArgument = 6,   // the service rejected a field (INVALID_ARGUMENT, OUT_OF_RANGE)
  kFailedPrecondition =
      7,                  // FAILED_PRECONDITION, ABORTED, ALREADY_EXISTS: lease held, e-stop active
  kPermissionDenied = 8,  // UNAUTHENTICATED, PERMISSION_DENIED: missing or wrong token/certificate
  kResourceExhausted = 9,  // RESOURCE_EXHAUSTED: rate or size limits
  kTaskFailed = 10,        // a followed task ended FAILED
  kTaskCancelled = 11,     // a followed task ended CANCELLED
};

// The exit code for a call that ended with `code` (gRPC and absl codes are numerically equal).
ExitCode ExitCodeFor(absl::StatusCode code);

inline int ToInt(ExitCode code) { return static_cast<int>(code); }

// "  0  ok\n  1  ..." for --help and docs.
std::string ExitCodeHelp();

}  // namespace semnav::cli
