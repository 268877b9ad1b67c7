#include "services/reasoning/server/camera_frame.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "services/common/status/grpc_status.h"

namespace semnav::reasoning {
namespace {

absl::Status Invalid(absl::string_view field, absl::string_view message) {
  return FieldError(absl::StatusCode::kInvalidArgument, field, message);
}

}  // namespace

absl::StatusOr<DecodedCameraFrame> DecodeCameraFrame(const v1::CameraFrame& frame) {
  const common::v1::Image& image = frame.image();
  DecodedCameraFrame out;
  switch (image.encoding()) {
    case common::v1::IMAGE_ENCODING_PNG:
    case common::v1::IMAGE_ENCODING_JPEG: {
      const cv::Mat bytes(1, static_cast<int>(image.data().size()), CV_8UC1,
                          const_cast<char*>(image.data().data()));
      out.image = cv::imdecode(bytes, cv::IMREAD_COLOR);
      if (out.image.empty())
        return Invalid("camera.image.data", "is not a decodable PNG/JPEG file");
      break;
    }
    case common::v1::IMAGE_ENCODING_RGB8: {
      if (image.data().size() != static_cast<std::size_t>(image.width()) * image.height() * 3 ||
          image.width() == 0) {
        return Invalid("camera.image.data", "RGB8 needs width * height * 3 bytes");
      }
      const cv::Mat rgb(static_cast<int>(image.height()), static_cast<int>(image.width()), CV_8UC3,
                        const_cast<char*>(image.data().data()));
      cv::cvtColor(rgb, out.image, cv::COLOR_RGB2BGR);
      break;
    }
    default:
      return Invalid("camera.image.encoding", "must be PNG, JPEG or RGB8");
  }
  const common::v1::CameraIntrinsics& k = frame.intrinsics();
  if (!(k.fx() > 0.0) || !(k.fy() > 0.0))
    return Invalid("camera.intrinsics.fx", "fx and fy must be > 0");
  if (k.width() != static_cast<uint32_t>(out.image.cols) ||
      k.height() != static_cast<uint32_t>(out.image.rows)) {
    return Invalid("camera.intrinsics.width", "width and height must equal the image's");
  }
  out.camera = PinholeCamera{k.fx(), k.fy(), k.cx(), k.cy(), out.image.cols, out.image.rows};
  const common::v1::Pose& pose = frame.camera_pose();
  out.position = Eigen::Vector3d(pose.position().x(), pose.position().y(), pose.position().z());
  const Eigen::Quaterniond q(pose.orientation().w(), pose.orientation().x(), pose.orientation().y(),
                             pose.orientation().z());
  if (!(q.norm() > 1e-9))
    return Invalid("camera.camera_pose.orientation", "must be a non-zero quaternion");
  out.orientation = q.normalized();
  return out;
}

std::string EncodePng(const cv::Mat& image) {
  std::vector<uchar> bytes;
  cv::imencode(".png", image, bytes);
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace semnav::reasoning
