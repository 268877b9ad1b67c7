#include "services/planning/core/clearance_cost.h"

#include <algorithm>
#include <cmath>

#include "services/planning/core/octile.h"

namespace semnav::planning {

std::vector<float> ClearanceCost(const PassabilityGrid& inflated, double resolution_m,
                                 const ClearanceConfig& config) {
  if (!config.enabled() || !(resolution_m > 0.0)) return {};
  const int w = inflated.width();
  const int h = inflated.height();
  // Two-pass chamfer transform with steps 1 and sqrt(2) (Borgefors): exactly the 8-connected
  // octile distance to the nearest blocked cell, in two sweeps instead of a Dijkstra.
  constexpr float kFar = 1e9f;
  const float diagonal = static_cast<float>(kSqrt2);
  std::vector<float> d(inflated.size(), kFar);
  bool any = false;
  for (int i = 0; i < inflated.size(); ++i) {
    if (inflated.values()[i] == 0) {
      d[i] = 0.0f;
      any = true;
    }
  }
  if (!any) return {};
  auto relax = [&](int i, int x, int y, float step) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    d[i] = std::min(d[i], d[inflated.Index(x, y)] + step);
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int i = inflated.Index(x, y);
      relax(i, x - 1, y, 1.0f);
      relax(i, x, y - 1, 1.0f);
      relax(i, x - 1, y - 1, diagonal);
      relax(i, x + 1, y - 1, diagonal);
    }
  }
  for (int y = h - 1; y >= 0; --y) {
    for (int x = w - 1; x >= 0; --x) {
      const int i = inflated.Index(x, y);
      relax(i, x + 1, y, 1.0f);
      relax(i, x, y + 1, 1.0f);
      relax(i, x + 1, y + 1, diagonal);
      relax(i, x - 1, y + 1, diagonal);
    }
  }
  const double reach_cells = config.clearance_m / resolution_m;
  std::vector<float> cost(inflated.size(), 0.0f);
  for (int i = 0; i < inflated.size(); ++i) {
    if (d[i] <= 0.0f || d[i] > reach_cells + 1e-6) continue;
    const double beyond_m = (d[i] - 1.0) * resolution_m;
    cost[i] =
        static_cast<float>(config.cost_penalty * std::exp(-config.cost_scaling_per_m * beyond_m));
  }
  return cost;
}

}  // namespace semnav::planning
