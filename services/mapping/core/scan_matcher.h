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

namespace semnav::mapping {

// A planar rigid transform: p' = R(yaw) p + (x, y).
struct PlanarCorrection {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;

  Eigen::Vector2d Apply(const Eigen::Vector2d& p) const;
  // (this after other): p -> this(other(p)).
  PlanarCorrection After(const PlanarCorrection& other) const;
};

// Occupied cells of a rectangle of the grid, row-major, nonzero = occupied.
struct OccupiedRaster {
  double resolution = 0.05;
  double origin_x = 0.0;  // outer corner of cell (row 0, column 0), metres
  double origin_y = 0.0;
  int width = 0;
  int height = 0;
  std::vector<uint8_t> occupied;
};

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

struct ScanMatchResult {
  PlanarCorrection correction;  // the refined correction (the coarse one when not refined)
  bool refined = false;
  double score = 0.0;         // mean likelihood at `correction`'s search optimum
  double coarse_score = 0.0;  // mean likelihood at the coarse pose
  int scan_cells = 0;
};

// Searches `correction` = local * coarse over the window, where local rotates about the scan's
// centroid (after `coarse`) and shifts by whole raster cells. `scan` holds obstacle points in the
// robot's reported frame. FailedPrecondition: fewer than min_scan_cells distinct scan cells.
absl::StatusOr<ScanMatchResult> MatchScan(const OccupiedRaster& map,
                                          const std::vector<Eigen::Vector2d>& scan,
                                          const PlanarCorrection& coarse,
                                          const ScanMatchConfig& config);

}  // namespace semnav::mapping
