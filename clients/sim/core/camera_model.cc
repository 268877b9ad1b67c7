#include "clients/sim/core/camera_model.h"

#include <cmath>

namespace semnav::sim {

Eigen::Isometry3d CameraPoseInWorld(const Eigen::Vector3d& position, double yaw, double pitch) {
  // Body frame (x forward, y left, z up) to optical frame (x right, y down, z forward).
  Eigen::Matrix3d body_from_optical;
  body_from_optical << 0, 0, 1,  //
      -1, 0, 0,                  //
      0, -1, 0;
  const Eigen::Matrix3d world_from_body = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                           Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()))
                                              .toRotationMatrix();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = world_from_body * body_from_optical;
  pose.translation() = position;
  return pose;
}

Eigen::Vector3d PixelRay(const CameraIntrinsics& intrinsics, double u, double v) {
  return Eigen::Vector3d((u - intrinsics.cx) / intrinsics.fx, (v - intrinsics.cy) / intrinsics.fy,
                         1.0)
      .normalized();
}

}  // namespace semnav::sim
