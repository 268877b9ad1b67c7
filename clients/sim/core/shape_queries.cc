#include "clients/sim/core/shape_queries.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/packed_box.h"

namespace semnav::sim {
namespace {

std::optional<ShapeHit> RayPrism(const PrismShape& prism, const Eigen::Vector3d& origin,
                                 const Eigen::Vector3d& dir, double t_min, double t_max) {
  std::optional<ShapeHit> best;
  auto offer = [&](double t, const Eigen::Vector3d& normal) {
    if (t >= t_min && t <= t_max && (!best || t < best->t)) best = ShapeHit{t, normal};
  };
  if (dir.z() != 0.0) {
    for (double z : {prism.base_z, prism.top_z()}) {
      const double t = (z - origin.z()) / dir.z();
      const Eigen::Vector2d p = origin.head<2>() + t * dir.head<2>();
      if (PointInPolygon(prism.polygon, p)) {
        offer(t, Eigen::Vector3d(0, 0, dir.z() > 0 ? -1.0 : 1.0));
      }
    }
  }
  const Eigen::Vector2d o = origin.head<2>();
  const Eigen::Vector2d d = dir.head<2>();
  const size_t n = prism.polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d a = prism.polygon[j];
    const Eigen::Vector2d e = prism.polygon[i] - a;
    const double denom = d.x() * e.y() - d.y() * e.x();
    if (denom == 0.0) continue;  // parallel to the edge
    const Eigen::Vector2d ao = a - o;
    const double t = (ao.x() * e.y() - ao.y() * e.x()) / denom;
    const double s = (ao.x() * d.y() - ao.y() * d.x()) / denom;
    if (s < 0.0 || s > 1.0) continue;
    const double z = origin.z() + t * dir.z();
    if (z < prism.base_z || z > prism.top_z()) continue;
    Eigen::Vector3d normal(e.y(), -e.x(), 0.0);
    normal.normalize();
    if (normal.dot(dir) > 0) normal = -normal;
    offer(t, normal);
  }
  return best;
}

bool CircleTouchesPolygon(const Polygon2& polygon, const Eigen::Vector2d& center, double radius) {
  return PointInPolygon(polygon, center) || DistanceToPolygonBoundary(polygon, center) < radius;
}

}  // namespace

std::optional<ShapeHit> IntersectRay(const Shape& shape, const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& dir, double t_min, double t_max) {
  if (const auto* box = std::get_if<BoxShape>(&shape)) {
    const auto hit =
        IntersectPackedBox(PackedBox::From(*box), origin, dir, InverseDirection(dir), t_min, t_max);
    if (!hit) return std::nullopt;
    return ShapeHit{hit->t, hit->normal};
  }
  return RayPrism(std::get<PrismShape>(shape), origin, dir, t_min, t_max);
}

bool CylinderOverlaps(const Shape& shape, const Eigen::Vector2d& center, double radius, double z0,
                      double z1) {
  if (const auto* box = std::get_if<BoxShape>(&shape)) {
    if (z1 <= box->base_z || z0 >= box->top_z()) return false;
    return DistanceToBoxFootprint(*box, center) < radius;
  }
  const auto& prism = std::get<PrismShape>(shape);
  if (z1 <= prism.base_z || z0 >= prism.top_z()) return false;
  return CircleTouchesPolygon(prism.polygon, center, radius);
}

Eigen::AlignedBox3d ShapeBounds(const Shape& shape) {
  const auto [lo, hi] = FootprintBounds(shape);
  const double base = std::visit([](const auto& s) { return s.base_z; }, shape);
  return Eigen::AlignedBox3d(Eigen::Vector3d(lo.x(), lo.y(), base),
                             Eigen::Vector3d(hi.x(), hi.y(), ShapeTop(shape)));
}

}  // namespace semnav::sim
