#include "services/planning/server/grid_conversion.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/common/status/grpc_status.h"
#include "services/common/status/value_checks.h"
#include "services/planning/server/request_checks.h"

namespace semnav::planning {
namespace {

using semnav::common::v1::GridLayerKind;
using semnav::common::v1::GridMap;

constexpr uint8_t kUnknown = 255;
constexpr int64_t kMaxCells = int64_t{1} << 26;  // 8192 x 8192
// Cells larger than this are no grid a planner can use (and 1e300 would put every pose at 1e300).
constexpr double kMaxResolutionM = 100.0;
// Finer cells than 1 mm are no map: every metre-sized setting divided by them overflows int (the
// RPC fuzzer's 2026-11-29 input converted an infinite EROI edge in cells).
constexpr double kMinResolutionM = 1e-3;

absl::Status Invalid(const std::string& field, absl::string_view message) {
  return FieldError(absl::StatusCode::kInvalidArgument, field, message);
}

}  // namespace

absl::StatusOr<Cell> GridFrame::ToCell(const semnav::common::v1::Pose2D& pose,
                                       const std::string& field) const {
  if (absl::Status s = CheckPose2D(pose, field); !s.ok()) return s;
  const double col = std::floor((pose.x() - origin_x) / resolution);
  const double row = std::floor((pose.y() - origin_y) / resolution);
  if (!(col >= 0 && row >= 0 && col < width && row < height)) {
    return Invalid(field,
                   absl::StrCat(field, " (", pose.x(), ", ", pose.y(), ") m is outside the grid"));
  }
  return Cell{static_cast<int>(col), static_cast<int>(row)};
}

absl::StatusOr<Cell> GridFrame::ToCellAnywhere(const semnav::common::v1::Pose2D& pose,
                                               const std::string& field) const {
  if (absl::Status s = CheckPose2D(pose, field); !s.ok()) return s;
  const double col = std::floor((pose.x() - origin_x) / resolution);
  const double row = std::floor((pose.y() - origin_y) / resolution);
  // A pose this far out is no start a planner could pad to (and would overflow an int).
  constexpr double kMaxCellsOutside = 1 << 20;
  if (!(std::abs(col) < kMaxCellsOutside + width && std::abs(row) < kMaxCellsOutside + height)) {
    return Invalid(
        field, absl::StrCat(field, " (", pose.x(), ", ", pose.y(), ") m is far outside the grid"));
  }
  return Cell{static_cast<int>(col), static_cast<int>(row)};
}

semnav::common::v1::Pose2D GridFrame::ToPose(Cell cell) const {
  semnav::common::v1::Pose2D pose;
  pose.set_x(origin_x + (cell.x + 0.5) * resolution);
  pose.set_y(origin_y + (cell.y + 0.5) * resolution);
  return pose;
}

absl::StatusOr<GridFrame> ReadGridFrame(const GridMap& grid, const std::string& field) {
  if (!(grid.resolution() >= kMinResolutionM) || !(grid.resolution() <= kMaxResolutionM)) {
    return Invalid(field + ".resolution",
                   absl::StrCat("resolution must be a finite value in [", kMinResolutionM, ", ",
                                kMaxResolutionM, "]"));
  }
  if (absl::Status s = CheckPose2D(grid.origin(), field + ".origin"); !s.ok()) return s;
  if (absl::Status s = CheckMagnitude(grid.foot_height(), field + ".foot_height", kMaxCoordinateM);
      !s.ok()) {
    return s;
  }
  if (absl::Status s =
          CheckMagnitude(grid.ceiling_height(), field + ".ceiling_height", kMaxCoordinateM);
      !s.ok()) {
    return s;
  }
  const int64_t cells = int64_t{grid.width()} * grid.height();
  if (grid.width() == 0 || grid.width() > kMaxCells) {
    return Invalid(field + ".width", absl::StrCat("width x height must be in 1..", kMaxCells));
  }
  if (grid.height() == 0 || cells > kMaxCells) {
    return Invalid(field + ".height", absl::StrCat("width x height must be in 1..", kMaxCells));
  }
  for (int i = 0; i < grid.layers_size(); ++i) {
    if (static_cast<int64_t>(grid.layers(i).data().size()) != cells) {
      return Invalid(absl::StrCat(field, ".layers[", i, "].data"),
                     absl::StrCat("layer data has ", grid.layers(i).data().size(),
                                  " bytes, expected width x height = ", cells));
    }
  }
  return GridFrame{grid.resolution(), grid.origin().x(), grid.origin().y(),
                   static_cast<int>(grid.width()), static_cast<int>(grid.height())};
}

const std::string* FindLayer(const GridMap& grid, GridLayerKind kind) {
  for (const auto& layer : grid.layers()) {
    if (layer.kind() == kind) return &layer.data();
  }
  return nullptr;
}

absl::StatusOr<PassabilityGrid> ToPassability(const GridMap& grid, const TraversabilityRules& rules,
                                              const std::string& field) {
  PassabilityGrid out(static_cast<int>(grid.width()), static_cast<int>(grid.height()), 0);
  const std::string* hierarchical =
      FindLayer(grid, semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL);
  const std::string* occupancy = FindLayer(grid, semnav::common::v1::GRID_LAYER_KIND_OCCUPANCY);
  const std::string* layer = hierarchical != nullptr ? hierarchical : occupancy;
  if (layer == nullptr) {
    return FieldError(absl::StatusCode::kFailedPrecondition, field + ".layers",
                      "2D planning needs a HIERARCHICAL or OCCUPANCY layer", "LAYER_MISSING");
  }
  const int limit = hierarchical != nullptr ? 1 : rules.occupied_percent;
  for (int i = 0; i < out.size(); ++i) {
    const uint8_t v = static_cast<uint8_t>((*layer)[i]);
    out.values()[i] = v == kUnknown ? rules.unknown_is_free : v < limit;
  }
  return out;
}

CellGrid<uint8_t> ToObstacleProbability(const GridMap& grid) {
  const std::string* layer =
      FindLayer(grid, semnav::common::v1::GRID_LAYER_KIND_OBSTACLE_PROBABILITY);
  if (layer == nullptr) return {};
  CellGrid<uint8_t> out(static_cast<int>(grid.width()), static_cast<int>(grid.height()), 0);
  for (int i = 0; i < out.size(); ++i) {
    const uint8_t v = static_cast<uint8_t>((*layer)[i]);
    out.values()[i] = v == kUnknown ? 0 : v;
  }
  return out;
}

absl::StatusOr<CellGrid<uint8_t>> ToExplored(const GridMap& grid, const std::string& field) {
  const std::string* layer = FindLayer(grid, semnav::common::v1::GRID_LAYER_KIND_EXPLORED);
  if (layer == nullptr) {
    return FieldError(absl::StatusCode::kFailedPrecondition, field + ".layers",
                      "exploration needs an EXPLORED layer", "LAYER_MISSING");
  }
  CellGrid<uint8_t> out(static_cast<int>(grid.width()), static_cast<int>(grid.height()), 0);
  for (int i = 0; i < out.size(); ++i) out.values()[i] = (*layer)[i] != 0;
  return out;
}

absl::StatusOr<LayeredGrid> ToLayeredGrid(const GridMap& grid, bool unknown_is_free,
                                          const std::string& field) {
  const std::string* layer = FindLayer(grid, semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL);
  if (layer == nullptr) {
    return FieldError(absl::StatusCode::kFailedPrecondition, field + ".layers",
                      "JUMP_ASTAR needs a HIERARCHICAL layer", "LAYER_MISSING");
  }
  LayeredGrid out(static_cast<int>(grid.width()), static_cast<int>(grid.height()), 0);
  for (int i = 0; i < out.size(); ++i) {
    const uint8_t v = static_cast<uint8_t>((*layer)[i]);
    out.values()[i] = v == kUnknown ? (unknown_is_free ? 0 : kStructureValue)
                                    : (v > kStructureValue ? kStructureValue : v);
  }
  return out;
}

void StampContacts(const std::vector<Eigen::Vector2d>& contacts, double radius_m, GridMap& grid) {
  const int width = static_cast<int>(grid.width());
  const int height = static_cast<int>(grid.height());
  const double resolution = grid.resolution();
  std::string* hierarchical = nullptr;
  std::string* occupancy = nullptr;
  for (semnav::common::v1::GridLayer& layer : *grid.mutable_layers()) {
    if (layer.kind() == semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL)
      hierarchical = layer.mutable_data();
    if (layer.kind() == semnav::common::v1::GRID_LAYER_KIND_OCCUPANCY)
      occupancy = layer.mutable_data();
  }
  constexpr double kSameObstacleM = 0.5;
  constexpr uint8_t kTallestFlyable = kStructureValue - 1;
  // Cells whose centre lies within `reach` of `point`, and the cell under it.
  const auto for_cells_near = [&](const Eigen::Vector2d& point, double reach, auto&& visit) {
    const double col = (point.x() - grid.origin().x()) / resolution;
    const double row = (point.y() - grid.origin().y()) / resolution;
    const int under_x = static_cast<int>(std::floor(col));
    const int under_y = static_cast<int>(std::floor(row));
    const int span = static_cast<int>(std::ceil(reach / resolution));
    for (int y = std::max(under_y - span, 0); y <= std::min(under_y + span, height - 1); ++y) {
      for (int x = std::max(under_x - span, 0); x <= std::min(under_x + span, width - 1); ++x) {
        const double dx = (x + 0.5 - col) * resolution;
        const double dy = (y + 0.5 - row) * resolution;
        if ((x == under_x && y == under_y) || dx * dx + dy * dy <= reach * reach)
          visit(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x));
      }
    }
  };
  for (const Eigen::Vector2d& point : contacts) {
    if (hierarchical != nullptr) {
      uint8_t tallest = 0;
      for_cells_near(point, kSameObstacleM, [&](size_t i) {
        const auto v = static_cast<uint8_t>((*hierarchical)[i]);
        if (v != kUnknown && v < kStructureValue) tallest = std::max(tallest, v);
      });
      const uint8_t stamp = tallest > 0 ? tallest : kTallestFlyable;
      for_cells_near(point, radius_m, [&](size_t i) {
        const auto v = static_cast<uint8_t>((*hierarchical)[i]);
        if (v >= kStructureValue && v != kUnknown) return;
        (*hierarchical)[i] = static_cast<char>(v == kUnknown ? stamp : std::max(v, stamp));
      });
    }
    if (occupancy != nullptr)
      for_cells_near(point, radius_m, [&](size_t i) { (*occupancy)[i] = static_cast<char>(100); });
  }
}

}  // namespace semnav::planning
