#include "clients/sim/core/scene.h"

#include <algorithm>
#include <cmath>

#include "clients/sim/core/shape_queries.h"

namespace semnav::sim {
namespace {

SceneSolid MakeSolid(const Shape& shape, const Rgb& colour, const std::string& kind,
                     int object_index) {
  return SceneSolid{shape, colour, kind, object_index, ShapeBounds(shape)};
}

double AutomaticCellSize(const std::vector<SceneSolid>& solids, const Eigen::Vector3d& span) {
  for (double size : {1.0, 0.5}) {
    double references = 0.0;
    for (const SceneSolid& s : solids) {
      const Eigen::Vector3d cells = (s.bounds.sizes() / size).array().floor() + 1.0;
      references += cells.prod();
    }
    const double cells = ((span / size).array().ceil().max(1.0)).prod();
    if (references <= cells) return size;
  }
  return 0.25;
}

}  // namespace

Scene Scene::Build(const World& world, double cell_size) {
  Scene scene;
  scene.ceiling_height_ = world.ceiling_height;
  scene.floor_colour_ = world.floor_colour;
  for (const Obstacle& o : world.obstacles) {
    scene.solids_.push_back(MakeSolid(o.shape, o.colour, o.kind, -1));
  }
  for (size_t i = 0; i < world.objects.size(); ++i) {
    const ObjectInstance& o = world.objects[i];
    scene.solids_.push_back(MakeSolid(o.box, o.colour, "object", static_cast<int>(i)));
  }
  for (const SceneSolid& s : scene.solids_) {
    const auto* box = std::get_if<BoxShape>(&s.shape);
    scene.packed_.push_back(box ? PackedBox::From(*box) : PackedBox{});
    scene.is_box_.push_back(box ? 1 : 0);
  }
  Eigen::AlignedBox3d extent(Eigen::Vector3d(world.bounds_min.x(), world.bounds_min.y(), 0.0),
                             Eigen::Vector3d(world.bounds_max.x(), world.bounds_max.y(),
                                             std::max(world.ceiling_height, 1.0)));
  for (const SceneSolid& s : scene.solids_) extent.extend(s.bounds);
  scene.grid_origin_ = extent.min();
  const Eigen::Vector3d span = extent.sizes();
  scene.cell_size_ = cell_size > 0.0 ? cell_size : AutomaticCellSize(scene.solids_, span);
  for (int a = 0; a < 3; ++a) {
    scene.dims_[a] = std::max(1, static_cast<int>(std::ceil(span[a] / scene.cell_size_)));
  }
  const int cells = scene.dims_.prod();
  // Two passes (count, then fill) build the compressed cell lists.
  std::vector<uint32_t> counts(cells + 1, 0);
  auto for_each_cell = [&](const SceneSolid& s, auto&& fn) {
    const Eigen::Vector3i lo = scene.CellOf(s.bounds.min());
    const Eigen::Vector3i hi = scene.CellOf(s.bounds.max());
    for (int z = lo.z(); z <= hi.z(); ++z)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int x = lo.x(); x <= hi.x(); ++x) fn(scene.CellIndex(x, y, z));
  };
  for (const SceneSolid& s : scene.solids_) for_each_cell(s, [&](int c) { ++counts[c + 1]; });
  for (int c = 0; c < cells; ++c) counts[c + 1] += counts[c];
  scene.cell_start_ = counts;
  scene.cell_items_.resize(counts[cells]);
  for (uint32_t i = 0; i < scene.solids_.size(); ++i) {
    for_each_cell(scene.solids_[i], [&](int c) { scene.cell_items_[counts[c]++] = i; });
  }
  return scene;
}

Eigen::Vector3i Scene::CellOf(const Eigen::Vector3d& p) const {
  Eigen::Vector3i cell;
  for (int a = 0; a < 3; ++a) {
    const int i = static_cast<int>(std::floor((p[a] - grid_origin_[a]) / cell_size_));
    cell[a] = std::clamp(i, 0, dims_[a] - 1);
  }
  return cell;
}

std::optional<int> Scene::SolidTouchingCylinder(const Eigen::Vector2d& center, double radius,
                                                double z0, double z1) const {
  const Eigen::Vector3i lo = CellOf(Eigen::Vector3d(center.x() - radius, center.y() - radius, z0));
  const Eigen::Vector3i hi = CellOf(Eigen::Vector3d(center.x() + radius, center.y() + radius, z1));
  for (int z = lo.z(); z <= hi.z(); ++z) {
    for (int y = lo.y(); y <= hi.y(); ++y) {
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const auto [begin, end] = Cell(x, y, z);
        for (const uint32_t* it = begin; it != end; ++it) {
          if (CylinderOverlaps(solids_[*it].shape, center, radius, z0, z1)) {
            return static_cast<int>(*it);
          }
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace semnav::sim
