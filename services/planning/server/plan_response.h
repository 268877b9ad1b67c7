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

// What a flying segment's altitude is computed from: the grid's h_f and h_c (GridMap
// foot_height, ceiling_height) and the margin kept above the tallest obstacle.
struct FlightHeights {
  double foot_m = 0.0;
  double ceiling_m = 0.0;
  double margin_m = 0.0;
};

// Fills a PlanPathResponse from an improved Jump A* plan; flying segments get the altitude that
// clears their tallest obstacle (FlightAltitude).
void FillResponse(const GridFrame& frame, const MultiModalPath& path, const FlightHeights& heights,
                  semnav::planning::v1::PlanPathResponse* response);

// Attaches the typed PlanFailureDetail to a core planning failure (no-op
// for statuses without a plan failure kind).
void AttachPlanFailure(absl::Status& status, Cell start, Cell goal);

}  // namespace semnav::planning
