#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "services/planning/core/astar.h"
#include "services/planning/core/cell_grid.h"
#include "services/planning/core/clearance_cost.h"
#include "services/planning/core/grid_path.h"
#include "services/planning/core/jps.h"
#include "services/planning/core/search_limits.h"

namespace semnav::planning {

struct GridPlannerConfig {
  // Seed 004 sec. 2.5: first try a path over cells of zero obstacle
  // probability; if none exists, also allow cells up to this probability
  // (percent, 0-100).
  int max_low_probability_percent = 50;
  // A start cell blocked after footprint inflation (the robot stands near a wall, or map noise
  // under it) moves to the nearest free cell this close, metres; the path then begins with the
  // step from the robot to that cell. A free start boxed in by the inflation (NO_PATH) moves the
  // same way to the nearest cell the goal can be reached from. 0 = neither (START_OCCUPIED).
  double start_snap_radius_m = 0.5;
  // A start at most this far outside the grid (the robot at the edge of a map that has not yet
  // grown to cover it) is planned from: the grid is padded with free cells up to the start.
  // 0 = a start outside the grid is INVALID_ARGUMENT.
  double max_start_outside_m = 1.0;
  // A goal at most this far outside the grid (a target seen past the map's edge) is planned to
  // the nearest edge cell (goal_adjusted). 0 = a goal outside the grid is INVALID_ARGUMENT.
  double max_goal_outside_m = 1.0;
  // With outside_is_free (unknown space counts as free, e.g. while exploring), a goal up to this
  // far outside the grid is planned to itself: the grid is padded with free cells to reach it,
  // as Nav2 plans through unknown space with allow_unknown. Bounds the padding's memory.
  double max_free_goal_outside_m = 20.0;
  // Cost near obstacles beyond the hard inflation (Nav2 inflation layer style).
  ClearanceConfig clearance;
};

// The footprint work on one grid: `free` inflated by the robot's radius and, with clearance, the
// clearance cost over it. The same for every call on the same grid and radius, so a caller that
// keeps a grid (planning's kept live grid) prepares it once (GridPlanner::Prepare).
struct PreparedFootprint {
  double robot_radius_m = 0.0;
  bool with_clearance = false;
  PassabilityGrid inflated;
  std::vector<float> clearance_cost;  // empty without clearance
};

struct GridPlanRequest {
  PassabilityGrid free;  // base traversability (1 free, 0 blocked)
  // Seed 004 obstacle probability map, percent 0-100 per cell; empty = none.
  CellGrid<uint8_t> obstacle_probability;
  double resolution_m = 0.05;
  Cell start;  // may lie up to max_start_outside_m outside `free`
  Cell goal;
  double robot_radius_m = 0.0;    // footprint inflation radius; 0 = point robot
  double goal_tolerance_m = 0.0;  // an occupied goal may move this far to a free cell
  // Where the robot first saw the goal; set = the alternative point of
  // seed 004 may replace an occupied or unreachable goal.
  std::optional<Cell> first_sighting;
  bool use_jps = true;  // false: A*
  // Add the config's clearance cost (the robot's paths); false = the shortest path.
  bool keep_clearance = false;
  // Cells beyond the grid are free like its unknown cells (planning's grid.unknown_is_free).
  bool outside_is_free = false;
  SearchLimits limits;
  // Prepare(free, resolution_m, robot_radius_m, keep_clearance), made before; null or one that
  // does not fit (another radius, clearance or size) = prepared in the call.
  std::shared_ptr<const PreparedFootprint> prepared;
};

struct GridPlanResult {
  GridPath path;
  Cell planned_goal;              // the goal actually planned to
  Cell planned_start;             // the free cell the search began from
  bool start_adjusted = false;    // the start was occupied and moved to planned_start
  bool grid_padded = false;       // the start lay outside the grid, which was padded
  bool goal_adjusted = false;     // moved within goal_tolerance_m
  bool alternative_used = false;  // replaced by the seed 004 alternative point
  std::string adjustment_reason;  // why the goal changed; empty when it did not
  bool low_probability_cells_used = false;
};

// 2D planning on one grid: footprint inflation, the two-stage obstacle
// probability costs, goal tolerance and the alternative point, on top of
// JPS or A*. A start just outside the grid pads the grid; an occupied start
// snaps to the nearest free cell (both reported in the result). With
// clearance enabled the search is A* over the clearance cost (JPS has no
// costs) and the cell path is shortened by any-angle shortcuts that keep
// its clearance (ShortcutPath).
// Failures carry the typed PlanFailure of the last attempt.
class GridPlanner {
 public:
  explicit GridPlanner(GridPlannerConfig config) : config_(config) {}

  absl::StatusOr<GridPlanResult> Plan(const GridPlanRequest& request);
  // What Plan computes first for a request on `free` with this footprint and clearance.
  PreparedFootprint Prepare(const PassabilityGrid& free, double resolution_m, double robot_radius_m,
                            bool keep_clearance) const;

 private:
  absl::StatusOr<GridPath> Search(const PassabilityGrid& grid, Cell start, Cell goal,
                                  const GridPlanRequest& request);
  absl::StatusOr<GridPlanResult> PlanOn(const PassabilityGrid& grid,
                                        const GridPlanRequest& request);
  // Pads the grid out to a start outside it, and with pad_to_goal out to the goal too.
  absl::StatusOr<GridPlanResult> PlanPadded(const GridPlanRequest& request, bool pad_to_goal);
  absl::StatusOr<GridPlanResult> PlanInside(const GridPlanRequest& request);
  absl::StatusOr<GridPlanResult> PlanStages(const PassabilityGrid& grid,
                                            const GridPlanRequest& request);

  // Of the current query (points into its PreparedFootprint); null = none.
  const std::vector<float>* clearance_cost_ = nullptr;

  GridPlannerConfig config_;
  AStarPlanner astar_;
  JpsPlanner jps_;
};

}  // namespace semnav::planning
