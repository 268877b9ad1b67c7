#pragma once

#include "absl/status/status.h"
#include "services/planning/core/cell_grid.h"
#include "services/planning/core/grid_path.h"
#include "services/planning/core/plan_failure.h"
#include "services/planning/core/search_limits.h"
#include "services/planning/core/search_workspace.h"

namespace semnav::planning {

// INVALID_ARGUMENT naming "start"/"goal" when outside the grid; the typed
// START_OCCUPIED / GOAL_OCCUPIED failure when on a blocked cell.
absl::Status CheckEndpoints(const PassabilityGrid& grid, Cell start, Cell goal);

// Follows parent links from `goal` back to the start of the current query.
GridPath TracePath(const SearchWorkspace& workspace, int width, int goal);

// Best-first search loop shared by A*, JPS and Jump A*: queues `start`
// with priority h0 (the workspace must be Reset), pops cells in f order,
// calls expand(cell) to relax successors and polls `limits`. OK once `goal`
// is popped (its parents then trace the path), else NO_PATH, TIMEOUT or
// CANCELLED.
template <typename Expand>
absl::Status RunBestFirst(SearchWorkspace& workspace, int start, double h0, int goal,
                          const SearchLimits& limits, Expand expand) {
  workspace.Relax(start, 0.0, h0, -1);
  int current = 0;
  while (workspace.PopBest(&current)) {
    if (current == goal) return absl::OkStatus();
    if (workspace.expansions() % kLimitCheckInterval == 0) {
      if (absl::Status s = limits.Check(); !s.ok()) return s;
    }
    expand(current);
  }
  return MakePlanFailure(PlanFailure::kNoPath, "goal is not reachable from start");
}

// The 8 moves; the first four are cardinal.
inline constexpr int kMoveDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
inline constexpr int kMoveDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

// A diagonal move needs both orthogonally adjacent cells free (no corner
// cutting); a cardinal move only needs its target free.
inline bool CanMove(const PassabilityGrid& grid, int x, int y, int dx, int dy) {
  if (!IsFree(grid, x + dx, y + dy)) return false;
  return dx == 0 || dy == 0 || (IsFree(grid, x + dx, y) && IsFree(grid, x, y + dy));
}

}  // namespace semnav::planning
