#include "clients/sim/core/ray_caster.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "clients/sim/core/shape_queries.h"

namespace semnav::sim {

RayCaster::RayCaster(const Scene& scene) : scene_(scene), last_ray_(scene.solids().size(), 0) {}

std::optional<SceneHit> RayCaster::CastPlanes(const Eigen::Vector3d& origin,
                                              const Eigen::Vector3d& dir, double t_min,
                                              double t_max) const {
  std::optional<SceneHit> best;
  if (dir.z() < 0.0 && origin.z() > 0.0) {
    const double t = -origin.z() / dir.z();
    if (t >= t_min && t <= t_max) best = SceneHit{t, Eigen::Vector3d::UnitZ(), kFloorSurface};
  }
  const double ceiling = scene_.ceiling_height();
  if (ceiling > 0.0 && dir.z() > 0.0 && origin.z() < ceiling) {
    const double t = (ceiling - origin.z()) / dir.z();
    if (t >= t_min && t <= t_max && (!best || t < best->t)) {
      best = SceneHit{t, -Eigen::Vector3d::UnitZ(), kCeilingSurface};
    }
  }
  return best;
}

std::optional<SceneHit> RayCaster::Cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                        double t_min, double t_max) {
  std::optional<SceneHit> best = CastPlanes(origin, dir, t_min, t_max);
  double limit = best ? best->t : t_max;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double cs = scene_.cell_size();
  const Eigen::Vector3d lo = scene_.grid_origin();
  const Eigen::Vector3i dims = scene_.grid_dims();
  // Clip the ray to the grid box.
  double t0 = t_min, t1 = limit;
  for (int a = 0; a < 3; ++a) {
    const double hi = lo[a] + dims[a] * cs;
    if (dir[a] == 0.0) {
      if (origin[a] < lo[a] || origin[a] > hi) return best;
      continue;
    }
    double ta = (lo[a] - origin[a]) / dir[a], tb = (hi - origin[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1) return best;
  if (++ray_id_ == 0) {  // wrapped: reset stamps so no solid looks already tested
    std::fill(last_ray_.begin(), last_ray_.end(), 0);
    ray_id_ = 1;
  }
  const Eigen::Vector3d start = origin + t0 * dir;
  Eigen::Vector3i cell, step;
  Eigen::Vector3d t_next, t_delta;
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::clamp(static_cast<int>(std::floor((start[a] - lo[a]) / cs)), 0, dims[a] - 1);
    if (dir[a] > 0.0) {
      step[a] = 1;
      t_next[a] = (lo[a] + (cell[a] + 1) * cs - origin[a]) / dir[a];
      t_delta[a] = cs / dir[a];
    } else if (dir[a] < 0.0) {
      step[a] = -1;
      t_next[a] = (lo[a] + cell[a] * cs - origin[a]) / dir[a];
      t_delta[a] = -cs / dir[a];
    } else {
      step[a] = 0;
      t_next[a] = kInf;
      t_delta[a] = kInf;
    }
  }
  const auto& solids = scene_.solids();
  const Eigen::Vector3d inv_dir = InverseDirection(dir);
  const int stride[3] = {1, dims.x(), dims.x() * dims.y()};
  int index = scene_.CellIndex(cell.x(), cell.y(), cell.z());
  while (true) {
    const auto [begin, end] = scene_.CellAt(index);
    for (const uint32_t* it = begin; it != end; ++it) {
      if (last_ray_[*it] == ray_id_) continue;
      last_ray_[*it] = ray_id_;
      if (const PackedBox* box = scene_.packed_box(*it)) {
        if (const auto hit = IntersectPackedBox(*box, origin, dir, inv_dir, t_min, limit)) {
          best = SceneHit{hit->t, hit->normal, static_cast<int>(*it)};
          limit = hit->t;
        }
      } else if (const auto hit = IntersectRay(solids[*it].shape, origin, dir, t_min, limit)) {
        best = SceneHit{hit->t, hit->normal, static_cast<int>(*it)};
        limit = hit->t;
      }
    }
    int axis = 0;
    if (t_next.y() < t_next[axis]) axis = 1;
    if (t_next.z() < t_next[axis]) axis = 2;
    // Done once the next cell starts beyond the nearest hit or the clipped ray.
    if (t_next[axis] > std::min(limit, t1)) break;
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= dims[axis]) break;
    index += step[axis] * stride[axis];
    t_next[axis] += t_delta[axis];
  }
  return best;
}

}  // namespace semnav::sim
