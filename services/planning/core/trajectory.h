#pragma once

#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

// Seed 000 sec. 2.3, step 1: curvature-minimising smoothing of a discrete
// path. The path is resampled every spacing_m, then each interior point
// repeatedly moves by
//   w_data (original - p) + w_smooth (prev + next - 2 p),
// the gradient step of (data deviation + squared discrete curvature); a move
// that would put the point, or either adjoining segment, in a blocked cell
// is rejected, so the result never enters obstacles. Endpoints stay fixed.
struct SmoothingConfig {
  double spacing_m = 0.1;
  double weight_data = 0.1;
  double weight_smooth = 0.3;
  int iterations = 200;
};

// Seed 000 sec. 3.2 kinematic limits, used for the time allocation.
struct TimeAllocationConfig {
  double max_speed_mps = 1.0;
  double max_accel_mps2 = 2.0;
  double max_yaw_rate_rps = 2.0;
};

struct TrajectoryPoint {
  double x = 0.0;  // metres, same frame as the input
  double y = 0.0;
  double yaw = 0.0;    // heading of the next segment, radians
  double speed = 0.0;  // m/s
  double t = 0.0;      // seconds from the start
};

// Points are metres in the grid's frame: cell (c, r) covers
// [origin + c res, origin + (c + 1) res) on each axis.
struct GridGeometry {
  double resolution = 0.05;
  double origin_x = 0.0;
  double origin_y = 0.0;
};

std::vector<Point2> SmoothPath(const PassabilityGrid& grid, const GridGeometry& geometry,
                               const std::vector<Point2>& path, const SmoothingConfig& config);

// Seed 000 sec. 2.3, step 2: time allocation. Speed is limited by
// max_speed, by max_yaw_rate / |curvature| (three-point curvature), and by
// max_accel through a forward and a backward pass (start and end at rest);
// segment times follow from constant acceleration, dt = 2 ds / (v0 + v1).
std::vector<TrajectoryPoint> AllocateTime(const std::vector<Point2>& path,
                                          const TimeAllocationConfig& config);

}  // namespace semnav::planning
