#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "clients/sim/core/camera_model.h"
#include "clients/sim/core/detector.h"
#include "clients/sim/core/odometry.h"

namespace semnav::sim {

// One capture, as an adapter would stream it to mapping.
struct SensorFrame {
  uint64_t index = 0;
  double time_s = 0.0;                  // simulated seconds since the episode start
  Pose true_pose;                       // ground truth (for scoring, never for the agent)
  Pose odometry_pose;                   // what the robot believes (drifts if enabled)
  Eigen::Isometry3d world_from_camera;  // true optical-frame pose
  Eigen::Isometry3d odom_from_camera;   // optical-frame pose from odometry
  CameraIntrinsics intrinsics;
  std::vector<float> depth;    // row-major z-depth, metres; 0 = no return
  std::optional<cv::Mat> rgb;  // CV_8UC3 BGR when enabled
  DetectionFrame detections;   // empty when disabled
  bool detector_ran = false;   // detections were enabled for this frame
};

}  // namespace semnav::sim
