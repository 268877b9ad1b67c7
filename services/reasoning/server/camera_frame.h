// A robot session's CameraFrame as OpenCV and core values, validated (INVALID_ARGUMENT naming the
// field): colour image (PNG, JPEG or RGB8 -> BGR), pinhole intrinsics matching it, camera pose.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "absl/status/statusor.h"
#include "semnav/reasoning/v1/robot_session.pb.h"
#include "services/reasoning/core/inverse_mapping.h"

namespace semnav::reasoning {

struct DecodedCameraFrame {
  cv::Mat image;  // 8-bit BGR
  PinholeCamera camera;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               // map frame, metres
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // camera body -> map
};

absl::StatusOr<DecodedCameraFrame> DecodeCameraFrame(const v1::CameraFrame& frame);

// PNG file bytes of an 8-bit image.
std::string EncodePng(const cv::Mat& image);

}  // namespace semnav::reasoning
