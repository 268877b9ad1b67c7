#pragma once

#include <vector>

#include "absl/status/statusor.h"
#include "services/planning/core/cell_grid.h"
#include "services/planning/core/grid_path.h"
#include "services/planning/core/search_limits.h"
#include "services/planning/core/search_workspace.h"

namespace semnav::planning {

// A* on an 8-connected grid: cardinal cost 1, diagonal sqrt(2), no corner
// cutting, octile heuristic (consistent, so the first goal pop is optimal).
// Keeps its workspace between queries; not thread-safe, use one per thread.
// With `extra_cost` (one value >= 0 per cell, e.g. ClearanceCost) a step of
// length l from a to b costs l * (1 + (extra[a] + extra[b]) / 2); the octile
// heuristic stays admissible. length_cells is then the path's geometric length.
class AStarPlanner {
 public:
  absl::StatusOr<GridPath> Plan(const PassabilityGrid& grid, Cell start, Cell goal,
                                const SearchLimits& limits = {},
                                const std::vector<float>* extra_cost = nullptr);

 private:
  SearchWorkspace workspace_;
};

}  // namespace semnav::planning
