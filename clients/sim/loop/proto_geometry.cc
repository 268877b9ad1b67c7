#include "clients/sim/loop/proto_geometry.h"

#include <cmath>
#include <cstdint>

namespace semnav::sim::loop {

semnav::common::v1::Vector3 ToProtoVector(const Eigen::Vector3d& v) {
  semnav::common::v1::Vector3 out;
  out.set_x(v.x());
  out.set_y(v.y());
  out.set_z(v.z());
  return out;
}

semnav::common::v1::Pose ToProtoPose(const Eigen::Isometry3d& pose) {
  semnav::common::v1::Pose out;
  *out.mutable_position() = ToProtoVector(pose.translation());
  const Eigen::Quaterniond q(pose.rotation());
  out.mutable_orientation()->set_w(q.w());
  out.mutable_orientation()->set_x(q.x());
  out.mutable_orientation()->set_y(q.y());
  out.mutable_orientation()->set_z(q.z());
  return out;
}

semnav::common::v1::Pose ToProtoPose(const Pose& pose) {
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  iso.translate(pose.position);
  iso.rotate(Eigen::AngleAxisd(pose.yaw, Eigen::Vector3d::UnitZ()));
  return ToProtoPose(iso);
}

google::protobuf::Timestamp ToStamp(double time_s) {
  google::protobuf::Timestamp stamp;
  const double whole = std::floor(time_s);
  stamp.set_seconds(static_cast<int64_t>(whole));
  stamp.set_nanos(static_cast<int32_t>((time_s - whole) * 1e9));
  return stamp;
}

}  // namespace semnav::sim::loop
