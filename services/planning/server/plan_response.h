#pragma once

#include "absl/status/status.h"
#include "semnav/planning/v1/planning_service.pb.h"
#include "services/planning/core/grid_planner.h"
#include "services/planning/core/jump_astar.h"
#include "services/planning/server/grid_conversion.h"

namespace semnav::planning {

// Fills a PlanPathResponse from a 2D plan (one rolling segment, no energy).
void FillResponse(const GridFrame& frame, const GridPlanResult& result,
                  semnav::planning::v1::PlanPathResponse* response);

// Fills a PlanPathResponse from an improved Jump A* plan.
void FillResponse(const GridFrame& frame, const MultiModalPath& path,
                  semnav::planning::v1::PlanPathResponse* response);

// Attaches the typed PlanFailureDetail to a core planning failure (no-op
// for statuses without a plan failure kind).
void AttachPlanFailure(absl::Status& status, Cell start, Cell goal);

}  // namespace semnav::planning
