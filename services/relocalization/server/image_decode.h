#pragma once

#include <opencv2/core.hpp>

#include "absl/status/statusor.h"
#include "semnav/common/v1/image.pb.h"

namespace semnav::relocalization {

// A colour request image (PNG, JPEG or RGB8) as an 8-bit BGR cv::Mat for OpenCV DNN.
// INVALID_ARGUMENT naming "image.<field>" for other encodings, wrong sizes or bad bytes.
absl::StatusOr<cv::Mat> DecodeColorImage(const common::v1::Image& image);

}  // namespace semnav::relocalization
