#include "services/planning/core/clearance_cost.h"

#include <cmath>

#include "services/planning/core/grid_search_common.h"
#include "services/planning/core/octile.h"
#include "services/planning/core/search_workspace.h"

namespace semnav::planning {

std::vector<float> ClearanceCost(const PassabilityGrid& inflated, double resolution_m,
                                 const ClearanceConfig& config) {
  if (!config.enabled() || !(resolution_m > 0.0)) return {};
  const double reach_cells = config.clearance_m / resolution_m;
  // Multi-source Dijkstra from every blocked cell that touches free space, cut at reach.
  SearchWorkspace workspace;
  workspace.Reset(inflated.size());
  bool any = false;
  for (int y = 0; y < inflated.height(); ++y) {
    for (int x = 0; x < inflated.width(); ++x) {
      if (inflated.at(x, y) != 0) continue;
      const bool edge = IsFree(inflated, x + 1, y) || IsFree(inflated, x - 1, y) ||
                        IsFree(inflated, x, y + 1) || IsFree(inflated, x, y - 1);
      if (!edge) continue;
      workspace.Relax(inflated.Index(x, y), 0.0, 0.0, -1);
      any = true;
    }
  }
  if (!any) return {};
  std::vector<float> cost(inflated.size(), 0.0f);
  int current = 0;
  while (workspace.PopBest(&current)) {
    const double d = workspace.g(current);
    const Cell c = inflated.CellAt(current);
    if (inflated.at(c) != 0) {
      const double beyond_m = (d - 1.0) * resolution_m;
      cost[current] = static_cast<float>(config.cost_penalty *
                                         std::exp(-config.cost_scaling_per_m * beyond_m));
    }
    for (int m = 0; m < 8; ++m) {
      const int nx = c.x + kMoveDx[m];
      const int ny = c.y + kMoveDy[m];
      if (!IsFree(inflated, nx, ny)) continue;
      const int next = inflated.Index(nx, ny);
      if (workspace.Closed(next)) continue;
      const double g = d + (m < 4 ? 1.0 : kSqrt2);
      if (g > reach_cells + 1e-9) continue;
      workspace.Relax(next, g, g, current);
    }
  }
  return cost;
}

}  // namespace semnav::planning
