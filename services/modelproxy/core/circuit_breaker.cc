#include "services/modelproxy/core/circuit_breaker.h"

namespace semnav::modelproxy {

bool CircuitBreaker::Allow(absl::Time now) {
  absl::MutexLock lock(&mu_);
  if (consecutive_failures_ < policy_.failure_threshold) return true;
  if (now < open_until_ || probe_in_flight_) return false;
  probe_in_flight_ = true;
  return true;
}

void CircuitBreaker::RecordSuccess() {
  absl::MutexLock lock(&mu_);
  consecutive_failures_ = 0;
  probe_in_flight_ = false;
}

void CircuitBreaker::RecordFailure(absl::Time now) {
  absl::MutexLock lock(&mu_);
  ++consecutive_failures_;
  probe_in_flight_ = false;
  if (consecutive_failures_ >= policy_.failure_threshold) open_until_ = now + policy_.open_duration;
}

BreakerState CircuitBreaker::state(absl::Time now) const {
  absl::MutexLock lock(&mu_);
  if (consecutive_failures_ < policy_.failure_threshold) return BreakerState::kClosed;
  return now < open_until_ ? BreakerState::kOpen : BreakerState::kHalfOpen;
}

int CircuitBreaker::consecutive_failures() const {
  absl::MutexLock lock(&mu_);
  return consecutive_failures_;
}

}  // namespace semnav::modelproxy
