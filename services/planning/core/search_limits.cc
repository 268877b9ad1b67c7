#include "services/planning/core/search_limits.h"

#include "services/planning/core/plan_failure.h"

namespace semnav::planning {

absl::Status SearchLimits::Check() const {
  if (is_cancelled && is_cancelled()) {
    return MakePlanFailure(PlanFailure::kCancelled, "search cancelled by the caller");
  }
  if (deadline != absl::InfiniteFuture() && absl::Now() >= deadline) {
    return MakePlanFailure(PlanFailure::kTimeout, "search exceeded its deadline");
  }
  return absl::OkStatus();
}

}  // namespace semnav::planning
