#pragma once

#include <functional>

#include "absl/status/status.h"
#include "absl/time/time.h"

namespace semnav::planning {

// Stops a search when the caller's deadline passes or the caller cancels.
// Searches call Check() every few hundred expansions, so the overhead stays
// negligible while a cancel takes effect within microseconds.
struct SearchLimits {
  absl::Time deadline = absl::InfiniteFuture();
  // Returns true once the caller has cancelled (e.g. the gRPC context);
  // empty means "never cancelled".
  std::function<bool()> is_cancelled;

  // OK, or a typed TIMEOUT / CANCELLED plan failure.
  absl::Status Check() const;
};

// How many expansions pass between two SearchLimits::Check() calls.
inline constexpr int kLimitCheckInterval = 256;

}  // namespace semnav::planning
