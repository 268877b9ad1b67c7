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
absl::Status ValidateWindow(double min_x, double min_y, double max_x, double max_y, double resolution_m,
                            const WindowLimits& limits);

}  // namespace semnav::mapping
