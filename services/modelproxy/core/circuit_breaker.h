#pragma once
// Per-backend circuit breaker: after `failure_threshold` consecutive failures the backend is
// skipped for `open_duration`; then one probe call is let through (half-open) and its outcome
// closes or re-opens the circuit. Thread-safe; time is passed in so tests control it.
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

namespace semnav::modelproxy {

struct BreakerPolicy {
  int failure_threshold = 5;  // consecutive failures that open the circuit (>= 1)
  absl::Duration open_duration = absl::Seconds(30);
};

enum class BreakerState { kClosed, kOpen, kHalfOpen };

class CircuitBreaker {
 public:
  explicit CircuitBreaker(BreakerPolicy policy) : policy_(policy) {}

  // True if a call may go to the backend now. In half-open state only one probe is admitted
  // until its outcome is recorded.
  bool Allow(absl::Time now);
  void RecordSuccess();
  void RecordFailure(absl::Time now);

  BreakerState state(absl::Time now) const;
  int consecutive_failures() const;

 private:
  const BreakerPolicy policy_;
  mutable absl::Mutex mu_;
  int consecutive_failures_ ABSL_GUARDED_BY(mu_) = 0;
  absl::Time open_until_ ABSL_GUARDED_BY(mu_) = absl::InfinitePast();
  bool probe_in_flight_ ABSL_GUARDED_BY(mu_) = false;
};

}  // namespace semnav::modelproxy
