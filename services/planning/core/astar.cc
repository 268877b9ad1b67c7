#include "services/planning/core/astar.h"

#include "services/planning/core/grid_search_common.h"
#include "services/planning/core/octile.h"

namespace semnav::planning {

absl::StatusOr<GridPath> AStarPlanner::Plan(const PassabilityGrid& grid, Cell start, Cell goal,
                                            const SearchLimits& limits,
                                            const std::vector<float>* extra_cost) {
  if (absl::Status s = CheckEndpoints(grid, start, goal); !s.ok()) return s;
  workspace_.Reset(grid.size());
  const int goal_index = grid.Index(goal);
  const absl::Status status =
      RunBestFirst(workspace_, grid.Index(start), OctileDistance(start, goal), goal_index, limits,
                   [&](int current) {
                     const Cell c = grid.CellAt(current);
                     const double g = workspace_.g(current);
                     for (int m = 0; m < 8; ++m) {
                       if (!CanMove(grid, c.x, c.y, kMoveDx[m], kMoveDy[m])) continue;
                       const Cell n{c.x + kMoveDx[m], c.y + kMoveDy[m]};
                       const int next = grid.Index(n);
                       if (workspace_.Closed(next)) continue;
                       double step = m < 4 ? 1.0 : kSqrt2;
                       if (extra_cost != nullptr) {
                         step *= 1.0 + 0.5 * ((*extra_cost)[current] + (*extra_cost)[next]);
                       }
                       const double ng = g + step;
                       workspace_.Relax(next, ng, ng + OctileDistance(n, goal), current);
                     }
                   });
  if (!status.ok()) return status;
  GridPath path = TracePath(workspace_, grid.width(), goal_index);
  if (extra_cost != nullptr) {
    path.length_cells = 0.0;
    for (size_t i = 1; i < path.waypoints.size(); ++i) {
      path.length_cells += OctileDistance(path.waypoints[i - 1], path.waypoints[i]);
    }
  }
  return path;
}

}  // namespace semnav::planning
