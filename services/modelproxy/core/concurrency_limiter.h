#pragma once
// Caps the calls in flight to one backend; callers wait for a slot until their deadline.
#include <optional>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

namespace semnav::modelproxy {

class ConcurrencyLimiter {
 public:
  // Holds one slot; releases it on destruction.
  class Permit {
   public:
    explicit Permit(ConcurrencyLimiter* owner) : owner_(owner) {}
    Permit(Permit&& other) noexcept : owner_(other.owner_) { other.owner_ = nullptr; }
    Permit& operator=(Permit&&) = delete;
    ~Permit();

   private:
    ConcurrencyLimiter* owner_;
  };

  explicit ConcurrencyLimiter(int max_in_flight) : max_in_flight_(max_in_flight) {}

  // A permit, or nullopt if no slot freed up before `deadline`.
  std::optional<Permit> Acquire(absl::Time deadline);
  int in_flight() const;
  int max_in_flight() const { return max_in_flight_; }

 private:
  void Release();

  const int max_in_flight_;
  mutable absl::Mutex mu_;
  int in_flight_ ABSL_GUARDED_BY(mu_) = 0;
};

}  // namespace semnav::modelproxy
