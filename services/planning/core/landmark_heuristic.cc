#include "services/planning/core/landmark_heuristic.h"

#include <algorithm>
#include <limits>

#include "services/planning/core/grid_search_common.h"

namespace semnav::planning {
namespace {

// Walks the diagonal in from a corner to the first passable cell.
bool CornerLandmark(const LayeredGrid& grid, int corner, Cell* found) {
  const int dx = corner & 1 ? -1 : 1;
  const int dy = corner & 2 ? -1 : 1;
  Cell c{dx > 0 ? 0 : grid.width() - 1, dy > 0 ? 0 : grid.height() - 1};
  for (; grid.Contains(c); c = {c.x + dx, c.y + dy}) {
    if (Passable(grid, c.x, c.y)) {
      *found = c;
      return true;
    }
  }
  return false;
}

}  // namespace

void LandmarkHeuristic::Reset(const LayeredGrid& grid, const StepCosts& costs) {
  cells_.clear();
  for (int corner = 0; corner < 4; ++corner) {
    Cell c;
    const bool found = CornerLandmark(grid, corner, &c);
    if (found && std::find(cells_.begin(), cells_.end(), c) == cells_.end()) cells_.push_back(c);
  }
  landmarks_ = static_cast<int>(cells_.size());
  computed_ = 0;
  dist_.assign(static_cast<size_t>(grid.size()) * landmarks_,
               std::numeric_limits<double>::infinity());
  costs_ = costs;
  valid_ = true;
}

bool LandmarkHeuristic::AddLandmark(const LayeredGrid& grid) {
  if (computed_ == landmarks_) return false;
  SearchWorkspace workspace;
  workspace.Reset(grid.size());
  // Dijkstra (no goal, h = 0) over the same unit moves as the search.
  (void)RunBestFirst(workspace, grid.Index(cells_[computed_]), 0.0, -1, SearchLimits{},
                     [&](int current) {
                       ForEachMove(grid, grid.CellAt(current),
                                   [&](Cell n, MotionMode mode, double cells) {
                                     const int next = grid.Index(n);
                                     if (workspace.Closed(next)) return;
                                     const double g =
                                         workspace.g(current) + costs_.Of(mode) * cells;
                                     workspace.Relax(next, g, g, current);
                                   });
                     });
  for (int cell = 0; cell < grid.size(); ++cell) {
    if (workspace.Reached(cell)) {
      dist_[static_cast<size_t>(cell) * landmarks_ + computed_] = workspace.g(cell);
    }
  }
  ++computed_;
  return true;
}

void LandmarkHeuristic::Clear() {
  valid_ = false;
  cells_.clear();
  landmarks_ = 0;
  computed_ = 0;
  dist_.clear();
  goal_dist_.clear();
}

void LandmarkHeuristic::SetGoal(int goal_cell) {
  const double* d = dist_.data() + static_cast<size_t>(goal_cell) * landmarks_;
  goal_dist_.assign(d, d + landmarks_);
}

}  // namespace semnav::planning
