#include "services/planning/core/plan_failure.h"

#include <array>
#include <string>

#include "absl/strings/cord.h"
#include "services/common/status/field_error.h"

namespace semnav::planning {
namespace {

struct FailureInfo {
  PlanFailure failure;
  absl::string_view name;
  absl::StatusCode code;
};

constexpr std::array<FailureInfo, 5> kFailures = {{
    {PlanFailure::kStartOccupied, "START_OCCUPIED", absl::StatusCode::kFailedPrecondition},
    {PlanFailure::kGoalOccupied, "GOAL_OCCUPIED", absl::StatusCode::kFailedPrecondition},
    {PlanFailure::kNoPath, "NO_PATH", absl::StatusCode::kNotFound},
    {PlanFailure::kTimeout, "TIMEOUT", absl::StatusCode::kDeadlineExceeded},
    {PlanFailure::kCancelled, "CANCELLED", absl::StatusCode::kCancelled},
}};

const FailureInfo& Info(PlanFailure failure) { return kFailures[static_cast<size_t>(failure)]; }

}  // namespace

absl::Status MakePlanFailure(PlanFailure failure, absl::string_view message) {
  absl::Status status(Info(failure).code, message);
  status.SetPayload(kPlanFailurePayload, absl::Cord(Info(failure).name));
  // The typed failure is the ErrorInfo reason clients switch on (ToGrpcStatus reads it).
  status.SetPayload(kReasonPayloadUrl, absl::Cord(Info(failure).name));
  return status;
}

std::optional<PlanFailure> PlanFailureOf(const absl::Status& status) {
  const auto payload = status.GetPayload(kPlanFailurePayload);
  if (!payload) return std::nullopt;
  const std::string name(*payload);
  for (const FailureInfo& info : kFailures) {
    if (info.name == name) return info.failure;
  }
  return std::nullopt;
}

absl::string_view PlanFailureName(PlanFailure failure) { return Info(failure).name; }

}  // namespace semnav::planning
