#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>

#include "clients/sim/core/world.h"

// Exact geometric queries on one box or prism.
namespace semnav::sim {

struct ShapeHit {
  double t = 0.0;                                     // ray parameter (metres if dir is unit)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // outward surface normal at the hit
};

// First surface crossing of origin + t * dir with t in [t_min, t_max].
std::optional<ShapeHit> IntersectRay(const Shape& shape, const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& dir, double t_min, double t_max);

// True if an upright cylinder (footprint circle centre/radius, z in [z0, z1]) touches the shape.
bool CylinderOverlaps(const Shape& shape, const Eigen::Vector2d& center, double radius, double z0,
                      double z1);

Eigen::AlignedBox3d ShapeBounds(const Shape& shape);

}  // namespace semnav::sim
