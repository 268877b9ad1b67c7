#include "services/mapping/core/window_validation.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"

namespace semnav::mapping {
namespace {

absl::Status CheckCoordinate(double value, absl::string_view field, const WindowLimits& limits) {
  if (!std::isfinite(value)) return InvalidField(field, "must be finite");
  if (std::abs(value) > limits.max_abs_coordinate_m) {
    return InvalidField(field,
                        absl::StrCat("must be within +-", limits.max_abs_coordinate_m, " m"));
  }
  return absl::OkStatus();
}

}  // namespace

absl::Status ValidateWindow(double min_x, double min_y, double max_x, double max_y,
                            double resolution_m, const WindowLimits& limits) {
  const struct {
    double value;
    const char* field;
  } corners[] = {{min_x, "window.min.x"},
                 {min_y, "window.min.y"},
                 {max_x, "window.max.x"},
                 {max_y, "window.max.y"}};
  for (const auto& corner : corners) {
    if (absl::Status s = CheckCoordinate(corner.value, corner.field, limits); !s.ok()) return s;
  }
  if (!(max_x > min_x)) return InvalidField("window.max.x", "must be > window.min.x");
  if (!(max_y > min_y)) return InvalidField("window.max.y", "must be > window.min.y");
  // Both extents are finite and bounded here, so the product cannot overflow a double.
  const double cells = (std::floor(max_x / resolution_m) - std::floor(min_x / resolution_m) + 1) *
                       (std::floor(max_y / resolution_m) - std::floor(min_y / resolution_m) + 1);
  if (cells > static_cast<double>(limits.max_cells)) {
    return InvalidField("window", absl::StrCat("covers more than ", limits.max_cells, " cells of ",
                                               resolution_m, " m; ask for a smaller window"));
  }
  return absl::OkStatus();
}

absl::Status ValidateOccupancyBox(const double (&min)[3], const double (&max)[3],
                                  double resolution_m, double max_voxels,
                                  const WindowLimits& limits) {
  static constexpr const char* kMinFields[] = {"min.x", "min.y", "min.z"};
  static constexpr const char* kMaxFields[] = {"max.x", "max.y", "max.z"};
  for (int a = 0; a < 3; ++a) {
    if (absl::Status s = CheckCoordinate(min[a], kMinFields[a], limits); !s.ok()) return s;
    if (absl::Status s = CheckCoordinate(max[a], kMaxFields[a], limits); !s.ok()) return s;
  }
  double voxels = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (!(max[a] > min[a])) return InvalidField(kMaxFields[a], "must be > min");
    voxels *= (max[a] - min[a]) / resolution_m;
  }
  if (voxels > max_voxels) {
    return InvalidField("max",
                        absl::StrCat("box holds ", voxels, " voxels, more than ", max_voxels));
  }
  return absl::OkStatus();
}

}  // namespace semnav::mapping
