#pragma once
// A failure's "do not ask again before" hint: a vendor's HTTP Retry-After, carried as a status
// payload from the model proxy's HTTP backend, through the proxy's gRPC status (ToGrpcStatus puts
// it in ErrorInfo.metadata["retry_after_s"], FromGrpcStatus reads it back) to the gateway's call
// policy. absl only, so core code may use it.
#include <optional>
#include <string>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"
#include "absl/time/time.h"

namespace semnav {

// The ErrorInfo metadata key the hint travels under on the wire (seconds, decimal).
inline constexpr char kRetryAfterMetadataKey[] = "retry_after_s";

// Attaches (or replaces) the hint on a non-OK status; negative or infinite durations are ignored.
void SetRetryAfter(absl::Status& status, absl::Duration after);
// The hint, if the status carries one.
std::optional<absl::Duration> RetryAfter(const absl::Status& status);

// An HTTP Retry-After value in delta-seconds ("120", also "1.5"), at most a day; nullopt for an
// HTTP date or anything else (those are not honoured: the caller's back-off applies).
std::optional<absl::Duration> ParseRetryAfterSeconds(absl::string_view value);
// The hint as the wire carries it (seconds, three decimals); ParseRetryAfterSeconds reads it back.
std::string RetryAfterSecondsText(absl::Duration after);

}  // namespace semnav
