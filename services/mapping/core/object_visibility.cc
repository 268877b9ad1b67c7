#include "services/mapping/core/object_visibility.h"

#include <algorithm>
#include <cmath>

#include "services/mapping/core/depth_projection.h"

namespace semnav::mapping {

double ApparentArea(const SceneObject& object, const Intrinsics& k, const CameraPose& pose,
                    double width, double height) {
  // The image rectangle around the box's corners in front of the camera, clipped to the image. A
  // flat box (a mat, or a false detection lifted onto the floor) has an area from above or at a
  // slant, where the width x height of its faces gave none.
  constexpr double kNearestZ = 0.05;
  double u_min = width, u_max = 0.0, v_min = height, v_max = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d offset(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5,
                                 corner & 4 ? 0.5 : -0.5);
    const Eigen::Vector3d camera =
        CameraFromMap(pose, object.position + offset.cwiseProduct(object.size));
    if (camera.z() < kNearestZ) continue;
    const Eigen::Vector2d pixel = PixelOf(k, camera);
    const double u = std::clamp(pixel.x(), 0.0, width);
    const double v = std::clamp(pixel.y(), 0.0, height);
    u_min = std::min(u_min, u);
    u_max = std::max(u_max, u);
    v_min = std::min(v_min, v);
    v_max = std::max(v_max, v);
  }
  return u_max > u_min && v_max > v_min ? (u_max - u_min) * (v_max - v_min) : 0.0;
}

bool ExpectedInView(const SceneObject& object, const cv::Mat& depth_m, const Intrinsics& k,
                    const CameraPose& pose, const ExistenceConfig& config) {
  if (depth_m.empty() || k.fx <= 0.0 || k.fy <= 0.0) return false;
  // Optical frame: x right, y down, z forward; map = R * camera + t.
  const Eigen::Vector3d camera = CameraFromMap(pose, object.position);
  const double z = camera.z();
  if (z <= 0.0 || z > config.max_range_m) return false;
  const Eigen::Vector2d pixel = PixelOf(k, camera);
  const double u = pixel.x();
  const double v = pixel.y();
  const double width = std::min<double>(k.width, depth_m.cols);
  const double height = std::min<double>(k.height, depth_m.rows);
  const double margin_u = config.image_margin * width, margin_v = config.image_margin * height;
  if (u < margin_u || u >= width - margin_u || v < margin_v || v >= height - margin_v) return false;
  if (ApparentArea(object, k, pose, width, height) < config.min_view_fraction * width * height)
    return false;
  const float reading = depth_m.at<float>(static_cast<int>(v), static_cast<int>(u));
  if (!(reading > 0.0f)) return false;
  const double half_extent = 0.5 * object.size.maxCoeff();
  return reading >= z - half_extent - config.occlusion_tolerance_m;
}

}  // namespace semnav::mapping
