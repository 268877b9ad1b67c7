#include "services/planning/core/trajectory.h"

#include <algorithm>
#include <cmath>

namespace semnav::planning {
namespace {

bool PointFree(const PassabilityGrid& grid, const GridGeometry& g, Point2 p) {
  const int c = static_cast<int>(std::floor((p.x - g.origin_x) / g.resolution));
  const int r = static_cast<int>(std::floor((p.y - g.origin_y) / g.resolution));
  return IsFree(grid, c, r);
}

// Samples the segment every quarter cell.
bool SegmentFree(const PassabilityGrid& grid, const GridGeometry& g, Point2 a, Point2 b) {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const int steps = std::max(1, static_cast<int>(std::ceil(length / (g.resolution / 4))));
  for (int k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) / steps;
    if (!PointFree(grid, g, {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)})) return false;
  }
  return true;
}

std::vector<Point2> Resample(const std::vector<Point2>& path, double spacing) {
  std::vector<Point2> out = {path.front()};
  for (size_t i = 1; i < path.size(); ++i) {
    const Point2 a = path[i - 1];
    const Point2 b = path[i];
    const int pieces =
        std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / spacing)));
    for (int k = 1; k <= pieces; ++k) {
      const double t = static_cast<double>(k) / pieces;
      out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  return out;
}

// Curvature of the circle through three points (0 when collinear).
double Curvature(Point2 a, Point2 b, Point2 c) {
  const double ab = std::hypot(b.x - a.x, b.y - a.y);
  const double bc = std::hypot(c.x - b.x, c.y - b.y);
  const double ca = std::hypot(a.x - c.x, a.y - c.y);
  const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const double denominator = ab * bc * ca;
  return denominator > 0.0 ? 2.0 * std::abs(cross) / denominator : 0.0;
}

}  // namespace

std::vector<Point2> SmoothPath(const PassabilityGrid& grid, const GridGeometry& geometry,
                               const std::vector<Point2>& path, const SmoothingConfig& config) {
  if (path.size() < 2) return path;
  const std::vector<Point2> original = Resample(path, config.spacing_m);
  std::vector<Point2> p = original;
  for (int it = 0; it < config.iterations; ++it) {
    for (size_t i = 1; i + 1 < p.size(); ++i) {
      const Point2 moved{p[i].x + config.weight_data * (original[i].x - p[i].x) +
                             config.weight_smooth * (p[i - 1].x + p[i + 1].x - 2 * p[i].x),
                         p[i].y + config.weight_data * (original[i].y - p[i].y) +
                             config.weight_smooth * (p[i - 1].y + p[i + 1].y - 2 * p[i].y)};
      if (SegmentFree(grid, geometry, p[i - 1], moved) &&
          SegmentFree(grid, geometry, moved, p[i + 1])) {
        p[i] = moved;
      }
    }
  }
  return p;
}

std::vector<TrajectoryPoint> AllocateTime(const std::vector<Point2>& path,
                                          const TimeAllocationConfig& config) {
  const size_t n = path.size();
  std::vector<TrajectoryPoint> out(n);
  if (n == 0) return out;
  std::vector<double> ds(n, 0.0);
  std::vector<double> v(n, config.max_speed_mps);
  for (size_t i = 0; i < n; ++i) {
    out[i].x = path[i].x;
    out[i].y = path[i].y;
    if (i > 0) ds[i] = std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
    if (i > 0 && i + 1 < n) {
      const double kappa = Curvature(path[i - 1], path[i], path[i + 1]);
      if (kappa > 0.0) v[i] = std::min(v[i], config.max_yaw_rate_rps / kappa);
    }
  }
  v.front() = 0.0;
  v.back() = 0.0;
  for (size_t i = 1; i < n; ++i) {
    v[i] = std::min(v[i], std::sqrt(v[i - 1] * v[i - 1] + 2 * config.max_accel_mps2 * ds[i]));
  }
  for (size_t i = n - 1; i-- > 0;) {
    v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2 * config.max_accel_mps2 * ds[i + 1]));
  }
  for (size_t i = 0; i < n; ++i) {
    out[i].speed = v[i];
    const size_t j = i + 1 < n ? i : i - (n > 1 ? 1 : 0);
    if (j + 1 < n) out[i].yaw = std::atan2(path[j + 1].y - path[j].y, path[j + 1].x - path[j].x);
    if (i > 0) {
      const double mean = v[i - 1] + v[i];
      out[i].t = out[i - 1].t + (mean > 0.0 ? 2.0 * ds[i] / mean : 0.0);
    }
  }
  return out;
}

}  // namespace semnav::planning
