#pragma once

#include "absl/status/statusor.h"
#include "services/planning/core/cell_grid.h"
#include "services/planning/core/grid_path.h"
#include "services/planning/core/search_limits.h"
#include "services/planning/core/search_workspace.h"

namespace semnav::planning {

// A* on an 8-connected grid: cardinal cost 1, diagonal sqrt(2), no corner
// cutting, octile heuristic (consistent, so the first goal pop is optimal).
// Keeps its workspace between queries; not thread-safe, use one per thread.
class AStarPlanner {
 public:
  absl::StatusOr<GridPath> Plan(const PassabilityGrid& grid, Cell start, Cell goal,
                                const SearchLimits& limits = {});

 private:
  SearchWorkspace workspace_;
};

}  // namespace semnav::planning
