#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

namespace semnav::mapping {

// Pinhole intrinsics of the depth camera (pixels).
struct Intrinsics {
  int width = 0;
  int height = 0;
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
};

enum class DepthEncoding { kUnknown, kMillimetres16U, kMetres32F };

// Raw depth bytes as received; decoded by DecodeDepth once validated.
struct DepthImage {
  int width = 0;
  int height = 0;
  DepthEncoding encoding = DepthEncoding::kUnknown;
  std::string data;
};

// Axis-aligned pixel box, [x_min, x_max) x [y_min, y_max).
struct PixelBox {
  double x_min = 0.0;
  double y_min = 0.0;
  double x_max = 0.0;
  double y_max = 0.0;
};

struct Detection {
  std::string label;
  double score = 0.0;
  PixelBox box;
  // Optional instance mask, row-major width*height of the depth image, nonzero = object.
  std::vector<uint8_t> mask;
  // Optional appearance embedding (e.g. CLIP); empty when absent.
  std::vector<float> embedding;
};

// Camera pose in the map frame: optical frame (x right, y down, z forward).
struct CameraPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

struct SensorFrame {
  std::string robot_id;
  int64_t stamp_ns = 0;
  Intrinsics intrinsics;
  DepthImage depth;
  CameraPose pose;
  // Optional encoded colour image (PNG or JPEG) aligned with the depth image.
  std::string rgb_encoded;
  std::vector<Detection> detections;
  // Optional LiDAR points in the camera frame (metres).
  std::vector<Eigen::Vector3f> lidar_points;
  // The robot does not trust `pose` (lost or relocalizing): see SceneObject::pose_untrusted.
  bool pose_untrusted = false;
  // The detector processed this frame: what it did not report counts as negative evidence.
  bool detector_ran = false;
};

}  // namespace semnav::mapping
