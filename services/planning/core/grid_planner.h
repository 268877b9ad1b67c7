#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "services/planning/core/astar.h"
#include "services/planning/core/cell_grid.h"
#include "services/planning/core/grid_path.h"
#include "services/planning/core/jps.h"
#include "services/planning/core/search_limits.h"

namespace semnav::planning {

struct GridPlannerConfig {
  // Seed 004 sec. 2.5: first try a path over cells of zero obstacle
  // probability; if none exists, also allow cells up to this probability
  // (percent, 0-100).
  int max_low_probability_percent = 50;
};

struct GridPlanRequest {
  PassabilityGrid free;  // base traversability (1 free, 0 blocked)
  // Seed 004 obstacle probability map, percent 0-100 per cell; empty = none.
  CellGrid<uint8_t> obstacle_probability;
  double resolution_m = 0.05;
  Cell start;
  Cell goal;
  double robot_radius_m = 0.0;    // footprint inflation radius; 0 = point robot
  double goal_tolerance_m = 0.0;  // an occupied goal may move this far to a free cell
  // Where the robot first saw the goal; set = the alternative point of
  // seed 004 may replace an occupied or unreachable goal.
  std::optional<Cell> first_sighting;
  bool use_jps = true;  // false: A*
  SearchLimits limits;
};

struct GridPlanResult {
  GridPath path;
  Cell planned_goal;               // the goal actually planned to
  bool goal_adjusted = false;      // moved within goal_tolerance_m
  bool alternative_used = false;   // replaced by the seed 004 alternative point
  std::string adjustment_reason;   // why the goal changed; empty when it did not
  bool low_probability_cells_used = false;
};

// 2D planning on one grid: footprint inflation, the two-stage obstacle
// probability costs, goal tolerance and the alternative point, on top of
// JPS or A*. Failures carry the typed PlanFailure of the last attempt.
class GridPlanner {
 public:
  explicit GridPlanner(GridPlannerConfig config) : config_(config) {}

  absl::StatusOr<GridPlanResult> Plan(const GridPlanRequest& request);

 private:
  absl::StatusOr<GridPath> Search(const PassabilityGrid& grid, Cell start, Cell goal,
                                  const GridPlanRequest& request);
  absl::StatusOr<GridPlanResult> PlanOn(const PassabilityGrid& grid,
                                        const GridPlanRequest& request);

  GridPlannerConfig config_;
  AStarPlanner astar_;
  JpsPlanner jps_;
};

}  // namespace semnav::planning
