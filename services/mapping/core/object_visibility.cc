#include "services/mapping/core/object_visibility.h"

#include <algorithm>
#include <cmath>

namespace semnav::mapping {

bool ExpectedInView(const SceneObject& object, const cv::Mat& depth_m, const Intrinsics& k,
                    const CameraPose& pose, const ExistenceConfig& config) {
  if (depth_m.empty() || k.fx <= 0.0 || k.fy <= 0.0) return false;
  // Optical frame: x right, y down, z forward; map = R * camera + t.
  const Eigen::Vector3d camera = pose.orientation.conjugate() * (object.position - pose.position);
  const double z = camera.z();
  if (z <= 0.0 || z > config.max_range_m) return false;
  const double u = k.fx * camera.x() / z + k.cx;
  const double v = k.fy * camera.y() / z + k.cy;
  const double width = std::min<double>(k.width, depth_m.cols);
  const double height = std::min<double>(k.height, depth_m.rows);
  const double margin_u = config.image_margin * width, margin_v = config.image_margin * height;
  if (u < margin_u || u >= width - margin_u || v < margin_v || v >= height - margin_v) return false;
  // Apparent extent: the larger horizontal size across, the height up.
  const double across = std::max(object.size.x(), object.size.y());
  const double projected = (k.fx * across / z) * (k.fy * object.size.z() / z);
  if (projected < config.min_view_fraction * width * height) return false;
  const float reading = depth_m.at<float>(static_cast<int>(v), static_cast<int>(u));
  if (!(reading > 0.0f)) return false;
  const double half_extent = 0.5 * object.size.maxCoeff();
  return reading >= z - half_extent - config.occlusion_tolerance_m;
}

}  // namespace semnav::mapping
