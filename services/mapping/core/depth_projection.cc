#include "services/mapping/core/depth_projection.h"

#include <cstring>

namespace semnav::mapping {

cv::Mat DecodeDepth(const DepthImage& depth) {
  cv::Mat metres(depth.height, depth.width, CV_32F);
  if (depth.encoding == DepthEncoding::kMetres32F) {
    std::memcpy(metres.data, depth.data.data(), depth.data.size());
    cv::patchNaNs(metres, 0.0);
    return metres;
  }
  cv::Mat millimetres(depth.height, depth.width, CV_16U);
  std::memcpy(millimetres.data, depth.data.data(), depth.data.size());
  millimetres.convertTo(metres, CV_32F, 1e-3);
  return metres;
}

Eigen::Vector3d BackProject(const Intrinsics& k, double u, double v, double z) {
  return {(u - k.cx) * z / k.fx, (v - k.cy) * z / k.fy, z};
}

Eigen::Vector2d PixelOf(const Intrinsics& k, const Eigen::Vector3d& camera) {
  return {k.fx * camera.x() / camera.z() + k.cx, k.fy * camera.y() / camera.z() + k.cy};
}

Eigen::Vector3d CameraFromMap(const CameraPose& pose, const Eigen::Vector3d& map_point) {
  return pose.orientation.conjugate() * (map_point - pose.position);
}

std::vector<Eigen::Vector3f> ProjectDepth(const cv::Mat& depth_m, const Intrinsics& k,
                                          const CameraPose& pose, const DepthRange& range,
                                          int stride) {
  const Eigen::Matrix3f rotation = pose.orientation.toRotationMatrix().cast<float>();
  const Eigen::Vector3f translation = pose.position.cast<float>();
  std::vector<Eigen::Vector3f> points;
  points.reserve(static_cast<size_t>(depth_m.rows / stride + 1) * (depth_m.cols / stride + 1));
  for (int v = 0; v < depth_m.rows; v += stride) {
    const float* row = depth_m.ptr<float>(v);
    for (int u = 0; u < depth_m.cols; u += stride) {
      const float z = row[u];
      if (!(z >= range.min_m && z <= range.max_m)) continue;
      const Eigen::Vector3f camera(static_cast<float>((u - k.cx) / k.fx) * z,
                                   static_cast<float>((v - k.cy) / k.fy) * z, z);
      points.push_back(rotation * camera + translation);
    }
  }
  return points;
}

}  // namespace semnav::mapping
