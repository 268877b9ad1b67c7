#include "services/planning/core/landmark_heuristic.h"

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

LandmarkHeuristic::LandmarkHeuristic(const LayeredGrid& grid, const StepCosts& costs)
    : costs_(costs) {
  std::vector<Cell> cells;
  for (int corner = 0; corner < kMaxLandmarks; ++corner) {
    Cell c;
    const bool found = CornerLandmark(grid, corner, &c);
    if (found && std::find(cells.begin(), cells.end(), c) == cells.end()) cells.push_back(c);
  }
  count_ = static_cast<int>(cells.size());
  dist_.assign(static_cast<size_t>(grid.size()) * count_, std::numeric_limits<double>::infinity());
  SearchWorkspace workspace;
  for (int l = 0; l < count_; ++l) {
    workspace.Reset(grid.size());
    // Dijkstra (no goal, h = 0) over the same unit moves as the search.
    (void)RunBestFirst(workspace, grid.Index(cells[l]), 0.0, -1, SearchLimits{}, [&](int current) {
      ForEachMove(grid, grid.CellAt(current), [&](Cell n, MotionMode mode, double length) {
        const int next = grid.Index(n);
        if (workspace.Closed(next)) return;
        const double g = workspace.g(current) + costs_.Of(mode) * length;
        workspace.Relax(next, g, g, current);
      });
    });
    for (int cell = 0; cell < grid.size(); ++cell) {
      if (workspace.Reached(cell))
        dist_[static_cast<size_t>(cell) * count_ + l] = workspace.g(cell);
    }
  }
}

LandmarkHeuristic::ToGoal LandmarkHeuristic::Towards(int goal_cell) const {
  ToGoal bound;
  bound.dist_ = dist_.data();
  bound.count_ = count_;
  std::copy_n(dist_.data() + static_cast<size_t>(goal_cell) * count_, count_, bound.goal_.begin());
  return bound;
}

}  // namespace semnav::planning
