#pragma once

#include "services/common/config/config_reader.h"
#include "services/planning/core/coverage_goal.h"
#include "services/planning/core/eroi_utility.h"
#include "services/planning/core/exploration_goal.h"
#include "services/planning/core/frontier_scoring.h"
#include "services/planning/core/trajectory.h"

namespace semnav::planning {

// YAML "planning.exploration": frontier, coverage-max, semantic scoring and
// EROI settings (lengths in metres here, cells in the core).
struct ExplorationConfig {
  int min_frontier_cells = 5;
  FrontierScoreConfig score;        // seed 002 weights 0.2/0.3/0.2/0.3
  FrontierValueConfig value;        // SEMANTIC_FRONTIER's value map (docs/algorithms/planning.md)
  SemanticDiscountConfig discount;  // SEMANTIC_FRONTIER's discounted nearest frontier (opt-in)
  CoverageGoalConfig coverage;      // L_MAX, turn step
  double eroi_size_m = 2.0;         // Delta
  int eroi_viewpoints = 8;
  double eroi_viewpoint_radius_m = 0.5;
  int eroi_rays = 72;
  double eroi_ray_range_m = 5.0;
  double eroi_connect_radius_m = 3.0;
  // eq. 24 lambda (the seed gives none): the utility halves every 3.5 m, as SEMANTIC_FRONTIER's
  // next-best-view decay. At 1.0 (halving every 0.7 m) the UAV went to the nearest pocket of
  // unknown, strip by strip (docs/performance/mission.md, "A gentler path cost").
  double eroi_lambda_per_m = 0.2;
  double eroi_k = 0.8;                    // eq. 24 tau = k max s
  bool eroi_clues_pay_extra_path = true;  // between clues, the farther pays the extra path
  // Viewpoints revealing less unknown area are dropped: about a bench's footprint (1.1 m^2), the
  // smallest target of the seed-000 scenes; smaller pockets are depth noise (our choice, the seed
  // gives no floor).
  double eroi_min_gain_m2 = 1.0;
  // A look at a sighting (SelectExplorationGoalRequest.look_at) moved off its straight line keeps
  // this far from the blocked cells on that line: a UAV's 0.3 m radius, the executor's re-plan
  // clearance up to 0.4 m, and the rest for the map's one-cell error (look_goal.h). The caller's
  // robot radius plus clearance, when larger, wins.
  double look_clearance_m = 1.0;

  EroiConfig EroiInCells(double resolution_m) const;
  ExplorationGoalConfig GoalConfig(double resolution_m) const;
  void Read(ConfigReader& section);
};

// YAML "planning.trajectory": seed 000 sec. 2.3 smoothing and limits.
struct TrajectoryConfig {
  SmoothingConfig smoothing;
  TimeAllocationConfig limits;  // 1.0 m/s, 2.0 m/s^2, 2.0 rad/s

  void Read(ConfigReader& section);
};

}  // namespace semnav::planning
