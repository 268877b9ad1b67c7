#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "clients/sim/core/world.h"

// A box prepared for fast ray tests: trigonometry done once; boxes turned by a multiple of
// 90 degrees (nearly all walls and furniture) take the axis-aligned slab test.
namespace semnav::sim {

struct PackedBox {
  double cx = 0, cy = 0, cos_yaw = 1, sin_yaw = 0, half_x = 0, half_y = 0, z0 = 0, z1 = 0;
  bool axis_aligned = true;

  static PackedBox From(const BoxShape& box) {
    PackedBox p{box.center.x(),    box.center.y(),   std::cos(box.yaw),
                std::sin(box.yaw), box.size.x() / 2, box.size.y() / 2,
                box.base_z,        box.top_z(),      false};
    if (std::abs(p.sin_yaw) < 1e-12 || std::abs(p.cos_yaw) < 1e-12) {
      if (std::abs(p.cos_yaw) < 1e-12) std::swap(p.half_x, p.half_y);
      p.axis_aligned = true;
      p.cos_yaw = 1.0;
      p.sin_yaw = 0.0;
    }
    return p;
  }
};

struct BoxRayHit {
  double t;
  Eigen::Vector3d normal;
};

// First entry of origin + t * dir into the box with t in [t_min, t_max]; `inv_dir` is
// 1 / dir per component (infinite for zero components).
inline std::optional<BoxRayHit> IntersectPackedBox(const PackedBox& b,
                                                   const Eigen::Vector3d& origin,
                                                   const Eigen::Vector3d& dir,
                                                   const Eigen::Vector3d& inv_dir, double t_min,
                                                   double t_max) {
  double o[3], inv[3];
  if (b.axis_aligned) {
    o[0] = origin.x() - b.cx;
    o[1] = origin.y() - b.cy;
    inv[0] = inv_dir.x();
    inv[1] = inv_dir.y();
  } else {
    const double dx = origin.x() - b.cx, dy = origin.y() - b.cy;
    o[0] = b.cos_yaw * dx + b.sin_yaw * dy;
    o[1] = -b.sin_yaw * dx + b.cos_yaw * dy;
    inv[0] = 1.0 / (b.cos_yaw * dir.x() + b.sin_yaw * dir.y());
    inv[1] = 1.0 / (-b.sin_yaw * dir.x() + b.cos_yaw * dir.y());
  }
  o[2] = origin.z();
  inv[2] = inv_dir.z();
  const double lo[3] = {-b.half_x, -b.half_y, b.z0};
  const double hi[3] = {b.half_x, b.half_y, b.z1};
  double t_enter = -std::numeric_limits<double>::infinity();
  double t_exit = std::numeric_limits<double>::infinity();
  int axis = 2;
  double sign = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (std::isinf(inv[a])) {  // parallel to this slab
      if (o[a] < lo[a] || o[a] > hi[a]) return std::nullopt;
      continue;
    }
    double t0 = (lo[a] - o[a]) * inv[a];
    double t1 = (hi[a] - o[a]) * inv[a];
    double s = -1.0;  // entering through the low face: the normal points to -axis
    if (t0 > t1) {
      std::swap(t0, t1);
      s = 1.0;
    }
    if (t0 > t_enter) {
      t_enter = t0;
      axis = a;
      sign = s;
    }
    t_exit = std::min(t_exit, t1);
  }
  if (t_enter > t_exit || t_enter > t_max || t_enter < t_min) return std::nullopt;
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
  local[axis] = sign;
  return BoxRayHit{t_enter,
                   Eigen::Vector3d(b.cos_yaw * local.x() - b.sin_yaw * local.y(),
                                   b.sin_yaw * local.x() + b.cos_yaw * local.y(), local.z())};
}

inline Eigen::Vector3d InverseDirection(const Eigen::Vector3d& dir) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return Eigen::Vector3d(dir.x() != 0 ? 1.0 / dir.x() : kInf, dir.y() != 0 ? 1.0 / dir.y() : kInf,
                         dir.z() != 0 ? 1.0 / dir.z() : kInf);
}

}  // namespace semnav::sim
