#include "services/modelproxy/core/retry_policy.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/cord.h"

namespace semnav::modelproxy {

absl::Duration RetryPolicy::Backoff(int retry, double u) const {
  const double base_s =
      std::min(absl::ToDoubleSeconds(max_backoff),
               absl::ToDoubleSeconds(initial_backoff) * std::pow(multiplier, retry));
  return absl::Seconds(base_s * (1.0 - jitter * u));
}

namespace {
constexpr char kNoRetryPayload[] = "semnav.modelproxy/no-retry";
}  // namespace

absl::Status MarkNotRetryable(absl::Status status) {
  status.SetPayload(kNoRetryPayload, absl::Cord("1"));
  return status;
}

bool IsRetryable(const absl::Status& status) {
  if (status.GetPayload(kNoRetryPayload).has_value()) return false;
  switch (status.code()) {
    case absl::StatusCode::kResourceExhausted:
    case absl::StatusCode::kUnavailable:
    case absl::StatusCode::kDeadlineExceeded:
      return true;
    default:
      return false;
  }
}

}  // namespace semnav::modelproxy
