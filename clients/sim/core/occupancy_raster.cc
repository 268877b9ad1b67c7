#include "clients/sim/core/occupancy_raster.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "clients/sim/core/geometry2d.h"

namespace semnav::sim {
namespace {

GroundTruthGrid EmptyGrid(const World& world, double resolution) {
  GroundTruthGrid grid;
  grid.origin = world.bounds_min;
  grid.resolution = resolution;
  const Eigen::Vector2d span = world.bounds_max - world.bounds_min;
  grid.width = static_cast<int>(std::ceil(span.x() / resolution));
  grid.height = static_cast<int>(std::ceil(span.y() / resolution));
  grid.cells.assign(static_cast<size_t>(grid.width) * grid.height, 0);
  return grid;
}

// True if the footprint comes within `margin` of the point, so walls thinner than a cell
// still mark a continuous line of cells.
bool CoversPoint(const Shape& shape, const Eigen::Vector2d& p, double margin) {
  if (const auto* box = std::get_if<BoxShape>(&shape)) {
    return DistanceToBoxFootprint(*box, p) < margin;
  }
  const auto& polygon = std::get<PrismShape>(shape).polygon;
  return PointInPolygon(polygon, p) || DistanceToPolygonBoundary(polygon, p) < margin;
}

// Calls paint(x, y) for each cell whose centre lies within half a cell of the footprint.
void ForEachCoveredCell(const GroundTruthGrid& grid, const Shape& shape,
                        const std::function<void(int, int)>& paint) {
  auto [lo, hi] = FootprintBounds(shape);
  lo.array() -= grid.resolution;
  hi.array() += grid.resolution;
  const int x0 =
      std::max(0, static_cast<int>(std::floor((lo.x() - grid.origin.x()) / grid.resolution)));
  const int y0 =
      std::max(0, static_cast<int>(std::floor((lo.y() - grid.origin.y()) / grid.resolution)));
  const int x1 =
      std::min(grid.width - 1, static_cast<int>((hi.x() - grid.origin.x()) / grid.resolution));
  const int y1 =
      std::min(grid.height - 1, static_cast<int>((hi.y() - grid.origin.y()) / grid.resolution));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d centre =
          grid.origin + grid.resolution * Eigen::Vector2d(x + 0.5, y + 0.5);
      if (CoversPoint(shape, centre, grid.resolution / 2 - 1e-9)) paint(x, y);
    }
  }
}

void ForEachSolid(const World& world,
                  const std::function<void(const Shape&, const std::string&)>& fn) {
  for (const Obstacle& o : world.obstacles) fn(o.shape, o.kind);
  for (const ObjectInstance& o : world.objects) fn(Shape(o.box), "object");
}

void Dilate(GroundTruthGrid& grid, double radius) {
  const int r = static_cast<int>(std::ceil(radius / grid.resolution));
  if (r <= 0) return;
  const std::vector<uint8_t> source = grid.cells;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (source[static_cast<size_t>(y) * grid.width + x] == 0) continue;
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= grid.width || ny >= grid.height) continue;
          if (std::hypot(dx, dy) * grid.resolution > radius + 1e-9) continue;
          grid.cells[static_cast<size_t>(ny) * grid.width + nx] = 100;
        }
      }
    }
  }
}

}  // namespace

RasterOptions BodyRaster(const RobotConfig& robot, double altitude) {
  RasterOptions raster;
  raster.robot_radius = robot.radius;
  raster.z_min = altitude + robot.ground_clearance;
  raster.z_max = altitude + robot.body_height;
  return raster;
}

GroundTruthGrid RasterizeOccupancy(const World& world, const RasterOptions& options) {
  GroundTruthGrid grid = EmptyGrid(world, options.resolution);
  ForEachSolid(world, [&](const Shape& shape, const std::string&) {
    const double base = std::visit([](const auto& s) { return s.base_z; }, shape);
    if (ShapeTop(shape) <= options.z_min || base >= options.z_max) return;
    ForEachCoveredCell(grid, shape, [&](int x, int y) {
      grid.cells[static_cast<size_t>(y) * grid.width + x] = 100;
    });
  });
  Dilate(grid, options.robot_radius);
  return grid;
}

GroundTruthGrid RasterizeHeightLayers(const World& world, double resolution, double ceiling_m) {
  GroundTruthGrid grid = EmptyGrid(world, resolution);
  ForEachSolid(world, [&](const Shape& shape, const std::string& kind) {
    const double top = ShapeTop(shape);
    const bool structure = IsStructure(kind) || top >= ceiling_m;
    const int value =
        structure ? 100 : std::clamp(static_cast<int>(std::ceil(top / ceiling_m * 99.0)), 1, 99);
    ForEachCoveredCell(grid, shape, [&](int x, int y) {
      uint8_t& cell = grid.cells[static_cast<size_t>(y) * grid.width + x];
      cell = std::max<uint8_t>(cell, static_cast<uint8_t>(value));
    });
  });
  return grid;
}

}  // namespace semnav::sim
