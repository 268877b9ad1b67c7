#pragma once
// Bounded retries with exponential backoff and jitter, only for transient failures.
#include "absl/status/status.h"
#include "absl/time/time.h"

namespace semnav::modelproxy {

struct RetryPolicy {
  int max_attempts = 3;  // attempts per backend per call, including the first (>= 1)
  absl::Duration initial_backoff = absl::Milliseconds(200);
  absl::Duration max_backoff = absl::Seconds(2);
  double multiplier = 2.0;  // >= 1
  double jitter = 0.5;      // 0 = none, 1 = full jitter (delay drawn from [0, base])

  // Delay before retry number `retry` (0 = first retry) given a uniform draw u in [0, 1):
  // base = min(max_backoff, initial_backoff * multiplier^retry); delay = base * (1 - jitter * u).
  absl::Duration Backoff(int retry, double u) const;
};

// 429 (RESOURCE_EXHAUSTED), 5xx (UNAVAILABLE) and timeouts (DEADLINE_EXCEEDED) are worth a
// retry; everything else (bad request, auth, malformed answer) is not, nor is any status
// marked with MarkNotRetryable (e.g. connection refused: UNAVAILABLE, but no server to retry).
bool IsRetryable(const absl::Status& status);
absl::Status MarkNotRetryable(absl::Status status);

}  // namespace semnav::modelproxy
