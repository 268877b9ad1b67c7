#pragma once

#include "absl/status/statusor.h"
#include "services/planning/core/cell_grid.h"
#include "services/planning/core/grid_path.h"
#include "services/planning/core/search_limits.h"
#include "services/planning/core/search_workspace.h"

namespace semnav::planning {

// Jump Point Search (Harabor & Grastien) with exactly the A* semantics of
// AStarPlanner: 8-connected, octile costs, no corner cutting (rules in
// jump_scan.h). Returns jump points as waypoints; the length equals A*'s.
class JpsPlanner {
 public:
  absl::StatusOr<GridPath> Plan(const PassabilityGrid& grid, Cell start, Cell goal,
                                const SearchLimits& limits = {});

 private:
  void TryDirection(const PassabilityGrid& grid, Cell from, int dx, int dy, Cell goal);

  SearchWorkspace workspace_;
};

}  // namespace semnav::planning
