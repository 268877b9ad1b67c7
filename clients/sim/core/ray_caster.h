#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "clients/sim/core/scene.h"

namespace semnav::sim {

inline constexpr int kFloorSurface = -1;
inline constexpr int kCeilingSurface = -2;

struct SceneHit {
  double t = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  int solid = kFloorSurface;  // index in Scene::solids(), or kFloorSurface / kCeilingSurface
};

// Casts rays through the scene's uniform grid (3D DDA, Amanatides & Woo 1987), testing each
// solid once per ray. Holds per-ray scratch state: one caster per thread.
class RayCaster {
 public:
  explicit RayCaster(const Scene& scene);
  // Nearest hit with t in [t_min, t_max]; `dir` should be unit length for t in metres.
  std::optional<SceneHit> Cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                               double t_min, double t_max);

 private:
  std::optional<SceneHit> CastPlanes(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                     double t_min, double t_max) const;

  const Scene& scene_;
  std::vector<uint32_t> last_ray_;  // per solid: id of the last ray that tested it
  uint32_t ray_id_ = 0;
};

}  // namespace semnav::sim
