#include "services/mapping/testing/frame_proto.h"

namespace semnav::mapping::testing {

v1::SensorFrame FrameToProto(const SensorFrame& f) {
  v1::SensorFrame p;
  p.mutable_header()->set_robot_id(f.robot_id);
  p.mutable_header()->mutable_stamp()->set_seconds(f.stamp_ns / 1'000'000'000);
  p.mutable_header()->mutable_stamp()->set_nanos(static_cast<int>(f.stamp_ns % 1'000'000'000));
  auto* k = p.mutable_intrinsics();
  k->set_width(f.intrinsics.width);
  k->set_height(f.intrinsics.height);
  k->set_fx(f.intrinsics.fx);
  k->set_fy(f.intrinsics.fy);
  k->set_cx(f.intrinsics.cx);
  k->set_cy(f.intrinsics.cy);
  p.mutable_depth()->set_width(f.depth.width);
  p.mutable_depth()->set_height(f.depth.height);
  p.mutable_depth()->set_encoding(f.depth.encoding == DepthEncoding::kMillimetres16U
                                      ? semnav::common::v1::IMAGE_ENCODING_DEPTH_16UC1_MM
                                      : semnav::common::v1::IMAGE_ENCODING_DEPTH_32FC1_M);
  p.mutable_depth()->set_data(f.depth.data);
  auto* pose = p.mutable_camera_pose();
  pose->mutable_position()->set_x(f.pose.position.x());
  pose->mutable_position()->set_y(f.pose.position.y());
  pose->mutable_position()->set_z(f.pose.position.z());
  pose->mutable_orientation()->set_w(f.pose.orientation.w());
  pose->mutable_orientation()->set_x(f.pose.orientation.x());
  pose->mutable_orientation()->set_y(f.pose.orientation.y());
  pose->mutable_orientation()->set_z(f.pose.orientation.z());
  return p;
}

}  // namespace semnav::mapping::testing
