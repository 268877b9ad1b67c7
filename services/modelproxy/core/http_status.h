#pragma once
// Maps a vendor's HTTP status to the status codes the retry policy understands.
#include <string>

#include "absl/status/status.h"

namespace semnav::modelproxy {

// 429 -> RESOURCE_EXHAUSTED, 408 -> DEADLINE_EXCEEDED, 5xx -> UNAVAILABLE (all retryable);
// 401 -> UNAUTHENTICATED, 403 -> PERMISSION_DENIED, 404 -> NOT_FOUND, other -> INVALID_ARGUMENT.
// The message is "HTTP <status>" plus `detail` when non-empty.
absl::Status StatusFromHttp(long http_status, const std::string& detail);

}  // namespace semnav::modelproxy
