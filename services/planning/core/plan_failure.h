#pragma once

#include <optional>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"

namespace semnav::planning {

// Why a plan could not be produced (in the spirit of Nav2's error codes).
// The server turns this into the typed proto detail PlanFailureDetail.
enum class PlanFailure {
  kStartOccupied,
  kGoalOccupied,
  kNoPath,
  kTimeout,
  kCancelled,
};

// The absl payload key carrying the failure kind inside a core status.
inline constexpr absl::string_view kPlanFailurePayload = "semnav.planning/plan_failure";

// A status with the canonical code for `failure` (FAILED_PRECONDITION for
// occupied endpoints, NOT_FOUND for no path, DEADLINE_EXCEEDED, CANCELLED)
// and the failure kind attached as payload.
absl::Status MakePlanFailure(PlanFailure failure, absl::string_view message);

// The failure kind attached by MakePlanFailure, if any.
std::optional<PlanFailure> PlanFailureOf(const absl::Status& status);

absl::string_view PlanFailureName(PlanFailure failure);

}  // namespace semnav::planning
