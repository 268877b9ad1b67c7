#include "services/planning/core/grid_search_common.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/planning/core/plan_failure.h"

namespace semnav::planning {
namespace {

absl::Status CheckInside(const PassabilityGrid& grid, Cell c, absl::string_view field) {
  if (grid.Contains(c)) return absl::OkStatus();
  return InvalidField(field, absl::StrCat(field, " (", c.x, ", ", c.y, ") is outside the ",
                                          grid.width(), " x ", grid.height(), " grid"));
}

}  // namespace

absl::Status CheckEndpoints(const PassabilityGrid& grid, Cell start, Cell goal) {
  if (absl::Status s = CheckInside(grid, start, "start"); !s.ok()) return s;
  if (absl::Status s = CheckInside(grid, goal, "goal"); !s.ok()) return s;
  if (grid.at(start) == 0) {
    return MakePlanFailure(PlanFailure::kStartOccupied,
                           absl::StrCat("start (", start.x, ", ", start.y, ") is occupied"));
  }
  if (grid.at(goal) == 0) {
    return MakePlanFailure(PlanFailure::kGoalOccupied,
                           absl::StrCat("goal (", goal.x, ", ", goal.y, ") is occupied"));
  }
  return absl::OkStatus();
}

GridPath TracePath(const SearchWorkspace& workspace, int width, int goal) {
  GridPath path;
  for (int cell = goal; cell >= 0; cell = workspace.parent(cell)) {
    path.waypoints.push_back({cell % width, cell / width});
  }
  std::reverse(path.waypoints.begin(), path.waypoints.end());
  path.length_cells = workspace.g(goal);
  path.expansions = workspace.expansions();
  return path;
}

}  // namespace semnav::planning
