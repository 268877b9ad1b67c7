#include "services/mapping/testing/frame_proto.h"

#include "services/mapping/testing/synthetic_room.h"

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

v1::SensorFrame StandardRoomFrameWithTable(int64_t stamp_ns, const std::vector<float>& embedding) {
  const CameraPose viewpoint = LookAt({0.5, 2.0, 1.2}, {4.0, 2.0, 0.0});
  v1::SensorFrame frame = FrameToProto(RenderFrame(StandardRoom(), viewpoint, stamp_ns));
  const Intrinsics k = Vga();
  const Eigen::Vector3d c =
      viewpoint.orientation.conjugate() * (Eigen::Vector3d(3.2, 1.3, 0.7) - viewpoint.position);
  const double u = k.fx * c.x() / c.z() + k.cx;
  const double v = k.fy * c.y() / c.z() + k.cy;
  v1::Detection* det = frame.add_detections();
  det->set_label("table");
  det->set_score(0.9);
  det->mutable_box()->set_x_min(u - 40);
  det->mutable_box()->set_y_min(v - 40);
  det->mutable_box()->set_x_max(u + 40);
  det->mutable_box()->set_y_max(v + 40);
  det->mutable_embedding()->Assign(embedding.begin(), embedding.end());
  return frame;
}

}  // namespace semnav::mapping::testing
