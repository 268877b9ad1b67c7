#include "clients/sim/loop/frame_encoder.h"

#include <algorithm>
#include <cstring>
#include <opencv2/imgproc.hpp>

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

void EncodeIntrinsics(const CameraIntrinsics& k, semnav::common::v1::CameraIntrinsics* out) {
  out->set_width(k.width);
  out->set_height(k.height);
  out->set_fx(k.fx);
  out->set_fy(k.fy);
  out->set_cx(k.cx);
  out->set_cy(k.cy);
}

}  // namespace

mapping::SensorFrame EncodeFrame(const SensorFrame& frame, const std::string& robot_id) {
  mapping::SensorFrame out;
  *out.mutable_header()->mutable_stamp() = ToStamp(frame.time_s);
  out.mutable_header()->set_robot_id(robot_id);
  out.mutable_header()->set_frame_id("camera");
  const CameraIntrinsics& k = frame.intrinsics;
  EncodeIntrinsics(k, out.mutable_intrinsics());
  auto* depth = out.mutable_depth();
  depth->set_width(k.width);
  depth->set_height(k.height);
  depth->set_encoding(semnav::common::v1::IMAGE_ENCODING_DEPTH_32FC1_M);
  // Little-endian float32, as on every platform we build for.
  std::string bytes(frame.depth.size() * sizeof(float), '\0');
  std::memcpy(bytes.data(), frame.depth.data(), bytes.size());
  depth->set_data(std::move(bytes));
  *out.mutable_camera_pose() = ToProtoPose(frame.odom_from_camera);
  for (const Detection& d : frame.detections.detections)
    EncodeDetection(d, k, out.add_detections());
  out.set_detector_ran(frame.detector_ran);
  return out;
}

absl::StatusOr<semnav::reasoning::v1::ConnectRequest> EncodeCameraFrame(const SensorFrame& frame) {
  if (!frame.rgb.has_value() || frame.rgb->empty()) {
    return absl::FailedPreconditionError("frame has no colour image (SensorConfig::rgb is off)");
  }
  semnav::reasoning::v1::ConnectRequest request;
  semnav::reasoning::v1::CameraFrame* camera = request.mutable_camera();
  cv::Mat rgb;
  cv::cvtColor(*frame.rgb, rgb, cv::COLOR_BGR2RGB);
  semnav::common::v1::Image* image = camera->mutable_image();
  image->set_width(rgb.cols);
  image->set_height(rgb.rows);
  image->set_encoding(semnav::common::v1::IMAGE_ENCODING_RGB8);
  image->set_data(
      std::string(reinterpret_cast<const char*>(rgb.data), rgb.total() * rgb.elemSize()));
  EncodeIntrinsics(frame.intrinsics, camera->mutable_intrinsics());
  // Optical axes (z forward, x right, y down) -> body axes (x forward, y left, z up).
  Eigen::Matrix3d optical_from_body;
  optical_from_body << 0, -1, 0,  //
      0, 0, -1,                   //
      1, 0, 0;
  Eigen::Isometry3d odom_from_body = frame.odom_from_camera;
  odom_from_body.linear() = frame.odom_from_camera.linear() * optical_from_body;
  *camera->mutable_camera_pose() = ToProtoPose(odom_from_body);
  return request;
}

}  // namespace semnav::sim::loop
