#include "services/modelproxy/core/concurrency_limiter.h"

namespace semnav::modelproxy {

ConcurrencyLimiter::Permit::~Permit() {
  if (owner_ != nullptr) owner_->Release();
}

std::optional<ConcurrencyLimiter::Permit> ConcurrencyLimiter::Acquire(absl::Time deadline) {
  auto has_slot = [this]() ABSL_SHARED_LOCKS_REQUIRED(mu_) { return in_flight_ < max_in_flight_; };
  if (!mu_.LockWhenWithDeadline(absl::Condition(&has_slot), deadline)) {
    mu_.Unlock();
    return std::nullopt;
  }
  ++in_flight_;
  mu_.Unlock();
  return Permit(this);
}

void ConcurrencyLimiter::Release() {
  absl::MutexLock lock(&mu_);
  --in_flight_;
}

int ConcurrencyLimiter::in_flight() const {
  absl::MutexLock lock(&mu_);
  return in_flight_;
}

}  // namespace semnav::modelproxy
