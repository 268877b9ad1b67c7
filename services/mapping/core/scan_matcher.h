// Correlative scan matching of a lost robot's look-around against the occupancy grid
// (docs/algorithms/relocalization.md, "Scan refinement"): a coarse pose from a few object
// landmarks (seed 001) leaves 2-10 deg of heading error when the objects lie 1-4 m apart; the
// walls and furniture the depth camera saw during the turn pin the pose down to a grid cell and
// half a degree. The search is exhaustive over a window around the coarse pose (Olson 2009,
// "Real-time correlative scan matching"; Cartographer's real-time correlative matcher) on a
// likelihood field: each scan cell scores exp(-d^2 / 2 sigma^2) for its distance d to the
// nearest occupied map cell.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "services/mapping/core/grid_layers.h"
#include "services/mapping/core/hierarchical_grid.h"

namespace semnav::mapping {

// A planar rigid transform: p' = R(yaw) p + (x, y).
struct PlanarCorrection {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;

  Eigen::Vector2d Apply(const Eigen::Vector2d& p) const;
  // (this after other): p -> this(other(p)).
  PlanarCorrection After(const PlanarCorrection& other) const;
  PlanarCorrection Inverse() const;
};

// Occupied cells of a rectangle of the grid, row-major, nonzero = occupied.
struct OccupiedRaster {
  double resolution = 0.05;
  double origin_x = 0.0;  // outer corner of cell (row 0, column 0), metres
  double origin_y = 0.0;
  int width = 0;
  int height = 0;
  std::vector<uint8_t> occupied;
  // Cells observed free, where a robot may stand (global search only; empty = anywhere).
  std::vector<uint8_t> observed_free;
  // Cells no camera sees past (walls: building structure; not a table the camera sees over),
  // for the global answer's ray check. Empty = every occupied cell.
  std::vector<uint8_t> opaque;
};

// The grid's `window` as a raster: occupied = obstacle or structure; with `free_and_opaque` also
// observed_free (kFree) and opaque (kStructure), which only the global search reads.
OccupiedRaster GridRaster(const HierarchicalGrid& grid, const GridWindow& window,
                          bool free_and_opaque);

struct ScanMatchConfig {
  // Search window around the coarse pose: the landmark answers of the kidnapped bench were off
  // by up to 0.31 m and 9.9 deg (docs/performance/mission.md, "Kidnapped robots recover").
  double linear_window_m = 0.5;
  double angular_window_rad = 0.26;  // 15 deg
  double angular_step_rad = 0.0087;  // 0.5 deg; the linear step is the raster's cell
  // Likelihood field: sigma of the distance to the nearest occupied cell.
  double sigma_m = 0.1;
  // The matched pose is taken only when its mean likelihood over the scan's cells reaches
  // min_score and beats the coarse pose's by min_gain; otherwise the coarse pose stands (a
  // scan of a place the map has not seen matches nothing).
  double min_score = 0.35;
  double min_gain = 0.02;
  int min_scan_cells = 30;
};

// The global search (MatchScanGlobally): every heading, every place the map saw free. Coarse
// pass on a lattice of `coarse_cells` cells, each scored by the maximum of the likelihood field
// over the shifts it stands for (an upper bound for them, as in Cartographer's branch-and-bound
// precomputation grids); the best mutually distinct poses are refined at full resolution.
struct GlobalMatchConfig {
  double angular_step_rad = 0.035;  // 2 deg
  int coarse_cells = 4;             // 20 cm at 5 cm cells
  int max_coarse_scan_cells = 250;  // the coarse pass scores an even subset of the scan
  int refine_candidates = 16;
  // A global answer is taken only when it is good and unique: its score reaches min_score, and
  // every refined pose farther than distinct_m / distinct_rad from it (and the robot's reported
  // pose) leaves at least min_misfit_ratio times its share of unexplained cells (1 - score). A
  // symmetric room would otherwise pick one of its look-alike poses; a room told apart only by a
  // cabinet in one corner (9 % of the scan) passes at 2.0.
  double min_score = 0.6;
  double min_misfit_ratio = 1.5;
  // The answer's rays from the robot to its scan cells must not cross the map's walls: at most
  // this share of them meets an opaque cell short of its last ray_end_slack_cells. A place the
  // map has not seen cannot score (the likelihood field rewards only hits), but a wrong place can
  // fit by chance; seeing through a wall it cannot (AMCL's beam model counts the same evidence).
  // Measured in the kidnapped bench group: right answers 0-9 % (the 9 %: walls the robot drew
  // at its wrong pose in the 2.5 s before it reported the loss), wrong candidates 18-65 %.
  double max_ray_conflicts = 0.1;
  int ray_end_slack_cells = 3;
  // A ray counts only once it comes out beyond the wall by this many cells: a ray to a point of
  // a wall the robot stands close to grazes that wall's cells on its way (a kidnapped robot
  // 15 cm from a door frame had 15 % of its right answer's rays graze it).
  int ray_emerge_cells = 3;
  double distinct_m = 1.0;
  double distinct_rad = 0.35;  // 20 deg
  // Poses within this of the robot's reported pose are no answer: the robot's own frames from
  // before it reported the loss may have drawn what it sees there. Their score still counts as
  // a competitor (the robot may not have moved at all).
  double self_match_m = 0.3;
  double self_match_rad = 0.09;  // 5 deg
};

struct ScanMatchResult {
  PlanarCorrection correction;  // the refined correction (the coarse one when not refined)
  bool refined = false;
  double score = 0.0;         // mean likelihood at `correction`'s search optimum
  double coarse_score = 0.0;  // mean likelihood at the coarse pose
  int scan_cells = 0;
  double runner_up_score = 0.0;  // global search: the best distinct pose's score
  double ray_conflicts = 0.0;    // global search: share of the answer's rays through a wall
};

// Searches `correction` = local * coarse over the window, where local rotates about the scan's
// centroid (after `coarse`) and shifts by whole raster cells. `scan` holds obstacle points in the
// robot's reported frame. FailedPrecondition: fewer than min_scan_cells distinct scan cells.
absl::StatusOr<ScanMatchResult> MatchScan(const OccupiedRaster& map,
                                          const std::vector<Eigen::Vector2d>& scan,
                                          const PlanarCorrection& coarse,
                                          const ScanMatchConfig& config);

// Searches the correction from the robot's reported frame to the map with no coarse pose: the
// robot (at `robot` in its reported frame) may stand on any observed-free cell at any heading.
// `refined` = a good, unique answer (GlobalMatchConfig); `correction` is the best pose found
// either way. FailedPrecondition: fewer than local.min_scan_cells distinct scan cells.
absl::StatusOr<ScanMatchResult> MatchScanGlobally(const OccupiedRaster& map,
                                                  const std::vector<Eigen::Vector2d>& scan,
                                                  const Eigen::Vector2d& robot,
                                                  const ScanMatchConfig& local,
                                                  const GlobalMatchConfig& config);

}  // namespace semnav::mapping
