// Sim value types -> common geometry protos (map frame = sim world frame).
#pragma once

#include <Eigen/Geometry>

#include "clients/sim/core/odometry.h"
#include "google/protobuf/timestamp.pb.h"
#include "semnav/common/v1/geometry.pb.h"

namespace semnav::sim::loop {

semnav::common::v1::Pose ToProtoPose(const Eigen::Isometry3d& pose);
// A planar robot pose: yaw about +z.
semnav::common::v1::Pose ToProtoPose(const Pose& pose);
semnav::common::v1::Vector3 ToProtoVector(const Eigen::Vector3d& v);
// Simulated seconds as a timestamp from the epoch (stamps only need to be monotonic per robot).
google::protobuf::Timestamp ToStamp(double time_s);

}  // namespace semnav::sim::loop
