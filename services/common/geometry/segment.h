// Point-to-segment distance in the plane, shared by the gateway (where a blocked robot was going)
// and the simulator (distances to footprint edges).
#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace semnav::geometry {

// Distance from `p` to the segment [a, b] (to `a` when the segment has no length).
inline double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace semnav::geometry
