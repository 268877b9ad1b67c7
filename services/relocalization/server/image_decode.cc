#include "services/relocalization/server/image_decode.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "absl/strings/str_cat.h"
#include "services/common/status/grpc_status.h"

namespace semnav::relocalization {

absl::StatusOr<cv::Mat> DecodeColorImage(const common::v1::Image& image) {
  const auto invalid = [](absl::string_view field, absl::string_view message) {
    return FieldError(absl::StatusCode::kInvalidArgument, field, message);
  };
  if (image.width() == 0 || image.height() == 0) {
    return invalid("image.width", "width and height must be > 0");
  }
  const int w = static_cast<int>(image.width()), h = static_cast<int>(image.height());
  cv::Mat bgr;
  switch (image.encoding()) {
    case common::v1::IMAGE_ENCODING_PNG:
    case common::v1::IMAGE_ENCODING_JPEG: {
      const std::vector<uchar> bytes(image.data().begin(), image.data().end());
      bgr = cv::imdecode(bytes, cv::IMREAD_COLOR);
      if (bgr.empty()) return invalid("image.data", "cannot decode the compressed image");
      if (bgr.cols != w || bgr.rows != h) {
        return invalid("image.width", absl::StrCat("decoded image is ", bgr.cols, "x", bgr.rows,
                                                   ", header says ", w, "x", h));
      }
      return bgr;
    }
    case common::v1::IMAGE_ENCODING_RGB8: {
      if (image.data().size() != static_cast<size_t>(w) * h * 3) {
        return invalid("image.data", absl::StrCat("RGB8 needs ", static_cast<size_t>(w) * h * 3,
                                                  " bytes, got ", image.data().size()));
      }
      const cv::Mat rgb(h, w, CV_8UC3, const_cast<char*>(image.data().data()));
      cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
      return bgr;
    }
    default:
      return invalid("image.encoding", "must be PNG, JPEG or RGB8");
  }
}

}  // namespace semnav::relocalization
