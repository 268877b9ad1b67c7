#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "clients/sim/core/packed_box.h"
#include "clients/sim/core/world.h"

// A world compiled for queries: every obstacle and object as a solid, bucketed in a
// uniform 3D grid so rays and collision checks only touch nearby solids.
namespace semnav::sim {

struct SceneSolid {
  Shape shape;
  Rgb colour;
  std::string kind;       // obstacle kind, or "object"
  int object_index = -1;  // index in World::objects, -1 for unlabelled obstacles
  Eigen::AlignedBox3d bounds;
};

class Scene {
 public:
  // The floor plane is z = 0; world.ceiling_height > 0 adds a ceiling plane. cell_size 0
  // picks the largest of 1, 0.5, 0.25 m giving at most one solid reference per cell on
  // average (dense geometry such as the FR-079 voxel boxes gets small cells).
  static Scene Build(const World& world, double cell_size = 0.0);

  const std::vector<SceneSolid>& solids() const { return solids_; }
  // Per solid, the packed form of a box (nullptr for prisms): a compact array the ray
  // caster walks instead of the larger SceneSolid records.
  const PackedBox* packed_box(uint32_t solid) const {
    return is_box_[solid] ? &packed_[solid] : nullptr;
  }
  double ceiling_height() const { return ceiling_height_; }
  Rgb floor_colour() const { return floor_colour_; }
  Rgb ceiling_colour() const { return Rgb{235, 235, 235}; }

  // Grid layout, read by the ray caster.
  const Eigen::Vector3d& grid_origin() const { return grid_origin_; }
  double cell_size() const { return cell_size_; }
  const Eigen::Vector3i& grid_dims() const { return dims_; }
  // Solid indices in cell (ix, iy, iz), which must be inside the grid.
  std::pair<const uint32_t*, const uint32_t*> Cell(int ix, int iy, int iz) const {
    return CellAt(CellIndex(ix, iy, iz));
  }
  // The same by linear index (x fastest, then y, then z).
  std::pair<const uint32_t*, const uint32_t*> CellAt(int c) const {
    return {cell_items_.data() + cell_start_[c], cell_items_.data() + cell_start_[c + 1]};
  }
  int CellIndex(int ix, int iy, int iz) const { return (iz * dims_.y() + iy) * dims_.x() + ix; }

  // Index of a solid touching an upright cylinder, if any.
  std::optional<int> SolidTouchingCylinder(const Eigen::Vector2d& center, double radius, double z0,
                                           double z1) const;

 private:
  Eigen::Vector3i CellOf(const Eigen::Vector3d& p) const;

  std::vector<SceneSolid> solids_;
  std::vector<PackedBox> packed_;
  std::vector<uint8_t> is_box_;
  double ceiling_height_ = 0.0;
  Rgb floor_colour_;
  Eigen::Vector3d grid_origin_ = Eigen::Vector3d::Zero();
  double cell_size_ = 0.5;
  Eigen::Vector3i dims_ = Eigen::Vector3i::Ones();
  std::vector<uint32_t> cell_start_;  // CSR offsets, size cells + 1
  std::vector<uint32_t> cell_items_;
};

}  // namespace semnav::sim
