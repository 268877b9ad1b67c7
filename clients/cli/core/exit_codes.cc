#include "clients/cli/core/exit_codes.h"

#include "absl/strings/str_format.h"

namespace semnav::cli {

ExitCode ExitCodeFor(absl::StatusCode code) {
  switch (code) {
    case absl::StatusCode::kOk:
      return ExitCode::kOk;
    case absl::StatusCode::kUnavailable:
      return ExitCode::kUnavailable;
    case absl::StatusCode::kDeadlineExceeded:
      return ExitCode::kDeadlineExceeded;
    case absl::StatusCode::kNotFound:
      return ExitCode::kNotFound;
    case absl::StatusCode::kInvalidArgument:
    case absl::StatusCode::kOutOfRange:
      return ExitCode::kInvalidArgument;
    case absl::StatusCode::kFailedPrecondition:
    case absl::StatusCode::kAborted:
    case absl::StatusCode::kAlreadyExists:
      return ExitCode::kFailedPrecondition;
    case absl::StatusCode::kUnauthenticated:
    case absl::StatusCode::kPermissionDenied:
      return ExitCode::kPermissionDenied;
    case absl::StatusCode::kResourceExhausted:
      return ExitCode::kResourceExhausted;
    default:
      return ExitCode::kError;
  }
}

std::string ExitCodeHelp() {
  struct Row {
    ExitCode code;
    const char* meaning;
  };
  static constexpr Row kRows[] = {
      {ExitCode::kOk, "ok (also: a followed task SUCCEEDED, or Ctrl-C detached from it)"},
      {ExitCode::kError, "other error (INTERNAL, UNKNOWN, DATA_LOSS, UNIMPLEMENTED, ...)"},
      {ExitCode::kUsage, "usage error: unknown command or flag, malformed value"},
      {ExitCode::kUnavailable, "service unreachable or not serving (UNAVAILABLE)"},
      {ExitCode::kDeadlineExceeded, "--deadline passed (DEADLINE_EXCEEDED)"},
      {ExitCode::kNotFound, "not found: unknown task, lease, map; no path (NOT_FOUND)"},
      {ExitCode::kInvalidArgument, "the service rejected a field (INVALID_ARGUMENT, OUT_OF_RANGE)"},
      {ExitCode::kFailedPrecondition,
       "failed precondition: lease held by another, e-stop active, task finished"},
      {ExitCode::kPermissionDenied,
       "missing or wrong token or certificate (UNAUTHENTICATED, PERMISSION_DENIED)"},
      {ExitCode::kResourceExhausted, "rate or size limit (RESOURCE_EXHAUSTED)"},
      {ExitCode::kTaskFailed, "the followed task ended FAILED"},
      {ExitCode::kTaskCancelled, "the followed task ended CANCELLED"},
  };
  std::string out;
  for (const Row& row : kRows)
    absl::StrAppendFormat(&out, "  %2d  %s\n", ToInt(row.code), row.meaning);
  return out;
}

}  // namespace semnav::cli
