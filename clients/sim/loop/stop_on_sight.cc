#include "clients/sim/loop/stop_on_sight.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/ray_caster.h"

namespace semnav::sim::loop {

size_t StopOnSight(const std::vector<Eigen::Vector2d>& path, const World& world, const Scene& scene,
                   const ObjectInstance& target, double camera_height, double half_fov_rad,
                   double range, double reach) {
  RayCaster caster(scene);
  const int target_index = static_cast<int>(&target - world.objects.data());
  const double aim_z = std::min(camera_height, 0.5 * target.box.size.z());
  std::vector<Eigen::Vector2d> aims = {target.box.center};
  for (const Eigen::Vector2d& corner : BoxCorners(target.box))
    aims.push_back(target.box.center + 0.9 * (corner - target.box.center));
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Eigen::Vector2d& p = path[i];
    if (DistanceToBoxFootprint(target.box, p) > reach) continue;
    const Eigen::Vector2d travel = path[std::min(i + 3, path.size() - 1)] - p;
    const double heading = std::atan2(travel.y(), travel.x());
    for (const Eigen::Vector2d& aim : aims) {
      const Eigen::Vector3d from(p.x(), p.y(), camera_height);
      const Eigen::Vector3d to(aim.x(), aim.y(), aim_z);
      const double length = (to - from).norm();
      const double bearing = std::atan2(to.y() - from.y(), to.x() - from.x());
      if (length > range || std::abs(std::remainder(bearing - heading, 2.0 * M_PI)) > half_fov_rad)
        continue;
      const std::optional<SceneHit> hit = caster.Cast(from, (to - from) / length, 0.0, range);
      if (hit.has_value() && hit->solid >= 0 &&
          scene.solids()[static_cast<size_t>(hit->solid)].object_index == target_index)
        return i;
    }
  }
  return path.empty() ? 0 : path.size() - 1;
}

}  // namespace semnav::sim::loop
