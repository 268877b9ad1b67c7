#pragma once

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "services/planning/core/energy_model.h"
#include "services/planning/core/landmark_heuristic.h"
#include "services/planning/core/layered_grid.h"
#include "services/planning/core/region_tables.h"
#include "services/planning/core/search_limits.h"
#include "services/planning/core/search_workspace.h"

namespace semnav::planning {

struct JumpAStarOptions {
  double resolution_m = 0.05;  // grid cell size
  // Eq. 14 weights f = alpha g + beta e + h (Table 1: 1.0 and 1.0).
  double alpha = 1.0;
  double beta = 1.0;
  // e(n) (eq. 13) enters eq. 14 in units of energy_unit_j. The seed does not
  // state the unit; in plain joules beta e outweighs alpha g 400:1 and
  // alpha/beta has no effect, so kJ is the default (see docs).
  double energy_unit_j = 1000.0;
  EnergyModel energy;
  // false: plain A* expansion everywhere (same costs), the reference used to
  // check that jump pruning keeps the optimum.
  bool jump_pruning = true;
};

// A maximal run of path cells travelled in one mode.
struct ModalSegment {
  Cell from;
  Cell to;
  int first_point = 0;  // index of `from` in MultiModalPath::waypoints
  int last_point = 0;   // index of `to`
  MotionMode mode = MotionMode::kRolling;
  double length_m = 0.0;
  double energy_j = 0.0;
  // Flying: the tallest obstacle value (1-99, eq. 3) of the cells the segment touches, what the
  // robot has to clear; 0 when rolling.
  uint8_t top = 0;
};

struct MultiModalPath {
  // Turning points: start, goal, and every cell where the heading or the
  // mode changes; consecutive points are joined by straight/45-degree runs.
  std::vector<Cell> waypoints;
  std::vector<ModalSegment> segments;
  double length_m = 0.0;
  double fly_m = 0.0;
  double roll_m = 0.0;
  double energy_j = 0.0;
  int switches = 0;   // mode changes along the path
  double cost = 0.0;  // alpha g + beta e at the goal
  int expansions = 0;
};

// Base altitude, metres above map z = 0, that clears an obstacle of hierarchical value `top` by
// margin_m: eq. 3 inverted, z = h_f + (top + 0.5) / 100 * (h_c - h_f) (the half unit covers the
// rounding of eq. 3). 0 when top is 0 or the grid carries no heights (ceiling_m <= foot_m).
double FlightAltitude(uint8_t top, double foot_m, double ceiling_m, double margin_m);

// Puts `start` before the path's first point (a start that snapped to a passable cell): the
// straight step joins the first segment, in its mode, and counts in the lengths and energies.
void PrependStart(Cell start, const JumpAStarOptions& options, MultiModalPath* path);

// The eq. 14 cost of one cell-length move in each mode under `options`.
StepCosts StepCostsOf(const JumpAStarOptions& options);

// INVALID_ARGUMENT naming "start"/"goal" outside the grid; the typed
// START_OCCUPIED / GOAL_OCCUPIED failure on building structure.
absl::Status CheckMultiModalEndpoints(const LayeredGrid& grid, Cell start, Cell goal);

// Improved Jump A* (seed 003, sec. 3.2): jump-point pruning inside uniform
// regions, plain A* expansion where the two modes meet. A move is rolling
// when every cell it touches (target, and for diagonals both orthogonal
// cells) is free, otherwise flying; structure is never entered and never
// corner-cut. Cells whose 8 neighbours include the other class (free vs
// obstacle) are "boundary" cells: jumps stop there and they are expanded
// to all 8 neighbours, so rolling/flying choices are made exactly as in A*.
// Away from boundaries every move in a region has one cost, so JPS pruning
// is exact: in free space (the seed's rolling JPS on the structure layer)
// and also inside obstacle interiors (an extension of the seed, whose A*
// expands them cell by cell; same optimum, measured in docs). A diagonal
// jump point whose straight jumps only reach fully expanded cells and whose f
// equals its parent's is not queued; its successors are relaxed directly
// (same costs, 3x fewer expansions on the seed map; see docs).
// h is the larger of (alpha + beta * rolling energy per metre) * octile
// distance (no metre costs less than rolling) and, when the caller has one
// for these costs, a landmark bound; both are admissible and consistent, so
// the optimum is unchanged.
// The planner keeps only its search workspace between queries (reuse it to
// avoid re-allocating); per-map state lives in RegionTables and
// LandmarkHeuristic, which JumpAStarCache keeps per map. Not thread-safe.
class JumpAStarPlanner {
 public:
  // One query on a grid with no prepared state: builds its region tables
  // first (the cold case).
  absl::StatusOr<MultiModalPath> Plan(const LayeredGrid& grid, Cell start, Cell goal,
                                      const JumpAStarOptions& options,
                                      const SearchLimits& limits = {});
  // One query on prepared per-map state. `landmarks` may be null; otherwise
  // it must have been built for StepCostsOf(options) on map.grid().
  absl::StatusOr<MultiModalPath> Plan(const RegionTables& map, const LandmarkHeuristic* landmarks,
                                      Cell start, Cell goal, const JumpAStarOptions& options,
                                      const SearchLimits& limits = {});

 private:
  // `regions` null: plain A* expansion everywhere.
  absl::StatusOr<MultiModalPath> Search(const LayeredGrid& grid, const RegionTables* regions,
                                        const LandmarkHeuristic* landmarks, Cell start, Cell goal,
                                        const JumpAStarOptions& options,
                                        const SearchLimits& limits);

  SearchWorkspace workspace_;
};

}  // namespace semnav::planning
