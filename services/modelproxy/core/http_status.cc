#include "services/modelproxy/core/http_status.h"

#include "absl/strings/str_cat.h"

namespace semnav::modelproxy {

absl::Status StatusFromHttp(long http_status, const std::string& detail) {
  const std::string message =
      absl::StrCat("HTTP ", http_status, detail.empty() ? "" : ": ", detail);
  if (http_status == 429) return absl::ResourceExhaustedError(message);
  if (http_status == 408) return absl::DeadlineExceededError(message);
  if (http_status >= 500) return absl::UnavailableError(message);
  if (http_status == 401) return absl::UnauthenticatedError(message);
  if (http_status == 403) return absl::PermissionDeniedError(message);
  if (http_status == 404) return absl::NotFoundError(message);
  return absl::InvalidArgumentError(message);
}

}  // namespace semnav::modelproxy
