#include "clients/sim/core/geometry2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace semnav::sim {

bool PointInPolygon(const Polygon2& polygon, const Eigen::Vector2d& point) {
  bool inside = false;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > point.y()) != (b.y() > point.y())) {
      const double x = a.x() + (point.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (point.x() < x) inside = !inside;
    }
  }
  return inside;
}

double PolygonArea(const Polygon2& polygon) {
  double twice = 0.0;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    twice += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
  }
  return std::abs(twice) / 2.0;
}

double DistanceToPolygonBoundary(const Polygon2& polygon, const Eigen::Vector2d& point) {
  double best = std::numeric_limits<double>::infinity();
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    best = std::min(best, DistanceToSegment(point, polygon[j], polygon[i]));
  }
  return best;
}

std::array<Eigen::Vector2d, 4> BoxCorners(const BoxShape& box) {
  const Eigen::Vector2d u(std::cos(box.yaw), std::sin(box.yaw));
  const Eigen::Vector2d v(-u.y(), u.x());
  const Eigen::Vector2d hu = u * box.size.x() / 2.0;
  const Eigen::Vector2d hv = v * box.size.y() / 2.0;
  return {box.center - hu - hv, box.center + hu - hv, box.center + hu + hv, box.center - hu + hv};
}

double DistanceToBoxFootprint(const BoxShape& box, const Eigen::Vector2d& point) {
  const Eigen::Vector2d d = point - box.center;
  const double c = std::cos(box.yaw), s = std::sin(box.yaw);
  const double local_x = c * d.x() + s * d.y();
  const double local_y = -s * d.x() + c * d.y();
  const double ex = std::max(std::abs(local_x) - box.size.x() / 2.0, 0.0);
  const double ey = std::max(std::abs(local_y) - box.size.y() / 2.0, 0.0);
  return std::hypot(ex, ey);
}

bool FootprintsOverlap(const BoxShape& a, const BoxShape& b, double clearance) {
  const auto ca = BoxCorners(a), cb = BoxCorners(b);
  for (const BoxShape* box : {&a, &b}) {
    const Eigen::Vector2d u(std::cos(box->yaw), std::sin(box->yaw));
    for (const Eigen::Vector2d& axis : {u, Eigen::Vector2d(-u.y(), u.x())}) {
      double a_lo = 1e300, a_hi = -1e300, b_lo = 1e300, b_hi = -1e300;
      for (const auto& p : ca) {
        a_lo = std::min(a_lo, p.dot(axis));
        a_hi = std::max(a_hi, p.dot(axis));
      }
      for (const auto& p : cb) {
        b_lo = std::min(b_lo, p.dot(axis));
        b_hi = std::max(b_hi, p.dot(axis));
      }
      if (a_hi + 2 * clearance <= b_lo || b_hi + 2 * clearance <= a_lo) return false;
    }
  }
  return true;
}

std::pair<Eigen::Vector2d, Eigen::Vector2d> FootprintBounds(const Shape& shape) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  auto grow = [&](const Eigen::Vector2d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  if (const auto* box = std::get_if<BoxShape>(&shape)) {
    for (const auto& c : BoxCorners(*box)) grow(c);
  } else {
    for (const auto& p : std::get<PrismShape>(shape).polygon) grow(p);
  }
  return {lo, hi};
}

}  // namespace semnav::sim
