#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

// Pinhole camera: intrinsics and the pose of its optical frame (x right, y down, z forward).
namespace semnav::sim {

// Defaults: 640 x 480 with fx = fy = 525, the Kinect / Orbbec Astra class of RGB-D sensor.
struct CameraIntrinsics {
  int width = 640;
  int height = 480;
  double fx = 525.0;
  double fy = 525.0;
  double cx = 319.5;
  double cy = 239.5;
};

// World pose of the optical frame for a body at `position` with heading `yaw`, the camera
// pitched down by `pitch` radians (0 = looking along the heading).
Eigen::Isometry3d CameraPoseInWorld(const Eigen::Vector3d& position, double yaw, double pitch);

// Unit ray through pixel (u, v) in the optical frame; pixel centres sit at integer coordinates.
Eigen::Vector3d PixelRay(const CameraIntrinsics& intrinsics, double u, double v);

}  // namespace semnav::sim
