#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "clients/sim/core/camera_model.h"
#include "clients/sim/core/scene.h"

namespace semnav::sim {

// What each pixel sees, noise free: the input to the depth, RGB and detection models.
struct RenderedView {
  CameraIntrinsics intrinsics;
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  std::vector<float> depth;      // z along the optical axis, metres; 0 = nothing in range
  std::vector<int32_t> surface;  // Scene solid index, kFloorSurface, kCeilingSurface; or
                                 // kNoSurface when depth is 0
  std::vector<float> shade;      // Lambert factor 0..1 for flat shading
  size_t PixelCount() const { return depth.size(); }
};

inline constexpr int32_t kNoSurface = -100;

// Casts one ray per pixel; hits with z-depth outside [min_range, max_range] read as 0.
RenderedView RenderView(const Scene& scene, const CameraIntrinsics& intrinsics,
                        const Eigen::Isometry3d& world_from_camera, double min_range,
                        double max_range);

}  // namespace semnav::sim
