#include "clients/sim/loop/frame_encoder.h"

#include <algorithm>
#include <cstring>

#include "clients/sim/loop/proto_geometry.h"

namespace semnav::sim::loop {
namespace {

namespace mapping = semnav::mapping::v1;

void EncodeDetection(const Detection& d, const CameraIntrinsics& k, mapping::Detection* out) {
  out->set_label(d.label);
  out->set_score(std::clamp(d.score, 0.0, 1.0));
  // The simulator's boxes are inclusive pixel ranges; the contract's are half-open.
  mapping::PixelBox* box = out->mutable_box();
  box->set_x_min(std::clamp(d.box[0], 0, k.width - 1));
  box->set_y_min(std::clamp(d.box[1], 0, k.height - 1));
  box->set_x_max(std::clamp(d.box[2] + 1, static_cast<int>(box->x_min()) + 1, k.width));
  box->set_y_max(std::clamp(d.box[3] + 1, static_cast<int>(box->y_min()) + 1, k.height));
  out->mutable_embedding()->Assign(d.embedding.begin(), d.embedding.end());
}

}  // namespace

mapping::SensorFrame EncodeFrame(const SensorFrame& frame, const std::string& robot_id) {
  mapping::SensorFrame out;
  *out.mutable_header()->mutable_stamp() = ToStamp(frame.time_s);
  out.mutable_header()->set_robot_id(robot_id);
  out.mutable_header()->set_frame_id("camera");
  const CameraIntrinsics& k = frame.intrinsics;
  auto* intrinsics = out.mutable_intrinsics();
  intrinsics->set_width(k.width);
  intrinsics->set_height(k.height);
  intrinsics->set_fx(k.fx);
  intrinsics->set_fy(k.fy);
  intrinsics->set_cx(k.cx);
  intrinsics->set_cy(k.cy);
  auto* depth = out.mutable_depth();
  depth->set_width(k.width);
  depth->set_height(k.height);
  depth->set_encoding(semnav::common::v1::IMAGE_ENCODING_DEPTH_32FC1_M);
  // Little-endian float32, as on every platform we build for.
  std::string bytes(frame.depth.size() * sizeof(float), '\0');
  std::memcpy(bytes.data(), frame.depth.data(), bytes.size());
  depth->set_data(std::move(bytes));
  *out.mutable_camera_pose() = ToProtoPose(frame.odom_from_camera);
  for (const Detection& d : frame.detections.detections) EncodeDetection(d, k, out.add_detections());
  return out;
}

}  // namespace semnav::sim::loop
