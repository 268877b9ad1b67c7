#pragma once

#include <cstdint>

#include "absl/status/status.h"

namespace semnav::mapping {

// Bounds on a requested map window, so no request can make mapping allocate without limit.
struct WindowLimits {
  // |x|, |y| of a window corner; beyond this a coordinate is not a place in any world we map.
  double max_abs_coordinate_m = 1e5;
  // Cells of one rendered window (6 byte layers each, plus the reply): 16 Mi cells ~ 100 MB.
  int64_t max_cells = int64_t{1} << 24;
};

// Checks a window [min, max] in metres before any cell is allocated. INVALID_ARGUMENT names
// the field ("window.min.x" ... "window", for the cell budget) and never echoes the value.
absl::Status ValidateWindow(double min_x, double min_y, double max_x, double max_y,
                            double resolution_m, const WindowLimits& limits);

// Checks an occupancy box [min, max] (fields "min.x" ... "max.z") before the octree is read:
// corners finite within limits.max_abs_coordinate_m, max > min on every axis, and at most
// `max_voxels` voxels of `resolution_m`.
absl::Status ValidateOccupancyBox(const double (&min)[3], const double (&max)[3],
                                  double resolution_m, double max_voxels,
                                  const WindowLimits& limits);

}  // namespace semnav::mapping
