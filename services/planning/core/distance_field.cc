#include "services/planning/core/distance_field.h"

#include "services/planning/core/grid_search_common.h"
#include "services/planning/core/octile.h"
#include "services/planning/core/search_workspace.h"

namespace semnav::planning {

std::vector<double> OctileDistanceField(const PassabilityGrid& grid, Cell from) {
  return OctileDistanceField(grid, std::vector<DistanceSource>{{from, 0.0}});
}

std::vector<double> OctileDistanceField(const PassabilityGrid& grid,
                                        const std::vector<DistanceSource>& sources) {
  std::vector<double> distance(grid.size(), kUnreachable);
  SearchWorkspace workspace;
  workspace.Reset(grid.size());
  for (const DistanceSource& source : sources) {
    if (!IsFree(grid, source.cell.x, source.cell.y)) continue;
    workspace.Relax(grid.Index(source.cell), source.distance, source.distance, -1);
  }
  int current = 0;
  while (workspace.PopBest(&current)) {
    distance[current] = workspace.g(current);
    const Cell c = grid.CellAt(current);
    for (int m = 0; m < 8; ++m) {
      if (!CanMove(grid, c.x, c.y, kMoveDx[m], kMoveDy[m])) continue;
      const int next = grid.Index(c.x + kMoveDx[m], c.y + kMoveDy[m]);
      if (workspace.Closed(next)) continue;
      const double g = workspace.g(current) + (m < 4 ? 1.0 : kSqrt2);
      workspace.Relax(next, g, g, current);
    }
  }
  return distance;
}

}  // namespace semnav::planning
