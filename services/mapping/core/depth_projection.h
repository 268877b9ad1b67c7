#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "services/mapping/core/sensor_frame.h"

namespace semnav::mapping {

// Valid depth range of the sensor; readings outside it are dropped.
struct DepthRange {
  double min_m = 0.3;
  double max_m = 8.0;
};

// Depth in metres as CV_32F (0 = no reading). The frame must have passed ValidateFrame.
cv::Mat DecodeDepth(const DepthImage& depth);

// Back-projects every `stride`-th pixel (rows and columns) with depth in range into the map
// frame: p = R * ((u - cx) z / fx, (v - cy) z / fy, z) + t.
std::vector<Eigen::Vector3f> ProjectDepth(const cv::Mat& depth_m, const Intrinsics& k,
                                          const CameraPose& pose, const DepthRange& range,
                                          int stride);

// Camera-frame point of pixel (u, v) at depth z (metres).
Eigen::Vector3d BackProject(const Intrinsics& k, double u, double v, double z);
// Pixel (u, v) of a camera-frame point in front of the camera (z > 0): BackProject's inverse.
Eigen::Vector2d PixelOf(const Intrinsics& k, const Eigen::Vector3d& camera);
// Camera-frame (optical) coordinates of a map-frame point: the inverse of map = R * camera + t.
Eigen::Vector3d CameraFromMap(const CameraPose& pose, const Eigen::Vector3d& map_point);

}  // namespace semnav::mapping
