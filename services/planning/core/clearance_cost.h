#pragma once

#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// Clearance beyond the footprint, in the style of Nav2's inflation layer: a free cell at
// distance d (metres, from the nearest blocked cell of the already inflated grid) costs
//   extra(d) = cost_penalty * exp(-cost_scaling_per_m * (d - resolution))   for d <= clearance_m
// on top of each step's length (0 beyond clearance_m). Nav2 defaults: cost_scaling_factor 3.0
// per metre (inflation layer), cost_penalty 2.0 (Smac planner's cost/252 weight).
struct ClearanceConfig {
  double clearance_m = 0.4;         // how far beyond the inflated obstacles cost reaches; 0 = off
  double cost_scaling_per_m = 3.0;  // exponential decay of the cost with distance
  double cost_penalty = 2.0;        // extra step cost right next to an inflated obstacle
  bool enabled() const { return clearance_m > 0.0 && cost_penalty > 0.0; }
};

// Extra cost per cell (0 on blocked cells and beyond reach), from the 8-connected (octile)
// chamfer distance to the nearest blocked cell. The grid's border is no obstacle (beyond it is
// unknown). Empty when no cell gets a cost (off, or nothing blocked).
std::vector<float> ClearanceCost(const PassabilityGrid& inflated, double resolution_m,
                                 const ClearanceConfig& config);

}  // namespace semnav::planning
