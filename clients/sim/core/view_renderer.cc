#include "clients/sim/core/view_renderer.h"

#include <algorithm>
#include <cmath>

#include "clients/sim/core/ray_caster.h"

namespace semnav::sim {

RenderedView RenderView(const Scene& scene, const CameraIntrinsics& intrinsics,
                        const Eigen::Isometry3d& world_from_camera, double min_range,
                        double max_range) {
  RenderedView view;
  view.intrinsics = intrinsics;
  view.world_from_camera = world_from_camera;
  const size_t n = static_cast<size_t>(intrinsics.width) * intrinsics.height;
  view.depth.assign(n, 0.0f);
  view.surface.assign(n, kNoSurface);
  view.shade.assign(n, 0.0f);
  RayCaster caster(scene);
  const Eigen::Vector3d origin = world_from_camera.translation();
  const Eigen::Matrix3d rotation = world_from_camera.linear();
  const Eigen::Vector3d light = Eigen::Vector3d(0.3, 0.5, 0.8).normalized();
  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) {
      const Eigen::Vector3d ray = PixelRay(intrinsics, u, v);
      // Range limits apply to z-depth, so t runs to max_range / cos(angle to the axis).
      const auto hit = caster.Cast(origin, rotation * ray, 0.0, max_range / ray.z());
      if (!hit) continue;
      const double z = hit->t * ray.z();
      if (z < min_range) continue;
      const size_t i = static_cast<size_t>(v) * intrinsics.width + u;
      view.depth[i] = static_cast<float>(z);
      view.surface[i] = hit->solid;
      view.shade[i] = static_cast<float>(0.45 + 0.55 * std::abs(hit->normal.dot(light)));
    }
  }
  return view;
}

}  // namespace semnav::sim
