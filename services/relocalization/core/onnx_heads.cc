#include "services/relocalization/core/onnx_heads.h"

#include <filesystem>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/string_view.h"
#include "services/common/status/field_error.h"

namespace semnav::relocalization {
namespace {

// Copies a [1, C, H, W] float blob into planar storage; checks H, W against `cells`.
absl::Status TakePlanes(const cv::Mat& blob, absl::string_view name, int* channels, int* height,
                        int* width, std::vector<float>* out) {
  if (blob.dims != 4 || blob.size[0] != 1 || blob.type() != CV_32F) {
    return absl::InvalidArgumentError(
        absl::StrCat("model output ", name, ": expected a [1, C, H, W] float tensor"));
  }
  if (*height != 0 && (blob.size[2] != *height || blob.size[3] != *width)) {
    return absl::InvalidArgumentError(
        absl::StrCat("model output ", name, ": grid differs from the heatmap's"));
  }
  *channels = blob.size[1];
  *height = blob.size[2];
  *width = blob.size[3];
  const float* data = blob.ptr<float>();
  out->assign(data, data + static_cast<size_t>(blob.total()));
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<std::unique_ptr<OnnxHeads>> OnnxHeads::Load(const OnnxHeadsConfig& config) {
  if (!std::filesystem::exists(config.model_path)) {
    return absl::NotFoundError(absl::StrCat("model_path: no file ", config.model_path));
  }
  if (config.input_width <= 0 || config.input_height <= 0) {
    return absl::InvalidArgumentError("input_width/input_height: must be > 0");
  }
  try {
    cv::dnn::Net net = cv::dnn::readNetFromONNX(config.model_path);
    if (net.empty()) {
      return absl::InvalidArgumentError(
          absl::StrCat("model_path: cannot load ", config.model_path));
    }
    return std::unique_ptr<OnnxHeads>(new OnnxHeads(config, std::move(net)));
  } catch (const cv::Exception& e) {
    return absl::InvalidArgumentError(absl::StrCat("model_path: ", e.what()));
  }
}

absl::StatusOr<HeadTensors> OnnxHeads::Run(const cv::Mat& image) {
  if (image.empty() || image.type() != CV_8UC3) {
    return InvalidField("image", "must be a non-empty 8-bit 3-channel image");
  }
  const cv::Mat blob = cv::dnn::blobFromImage(
      image, config_.pixel_scale, cv::Size(config_.input_width, config_.input_height),
      cv::Scalar(config_.mean_b, config_.mean_g, config_.mean_r), config_.swap_rb, false, CV_32F);
  std::vector<cv::String> names = {config_.heatmap_output, config_.offset_output,
                                   config_.size_output};
  if (!config_.feature_output.empty()) names.push_back(config_.feature_output);
  std::vector<cv::Mat> outputs;
  {
    absl::MutexLock lock(&mu_);
    try {
      net_.setInput(blob);
      net_.forward(outputs, names);
    } catch (const cv::Exception& e) {
      return absl::InternalError(absl::StrCat("model inference failed: ", e.what()));
    }
  }
  HeadTensors h;
  int channels = 0;
  if (auto s =
          TakePlanes(outputs[0], names[0], &h.heatmap_channels, &h.height, &h.width, &h.heatmap);
      !s.ok()) {
    return s;
  }
  for (size_t i = 1; i < 3; ++i) {
    std::vector<float>* dst = i == 1 ? &h.offset : &h.size;
    if (auto s = TakePlanes(outputs[i], names[i], &channels, &h.height, &h.width, dst); !s.ok()) {
      return s;
    }
    if (channels != 2) {
      return absl::InvalidArgumentError(
          absl::StrCat("model output ", names[i], ": needs 2 channels"));
    }
  }
  if (outputs.size() > 3) {
    if (auto s =
            TakePlanes(outputs[3], names[3], &h.feature_channels, &h.height, &h.width, &h.features);
        !s.ok()) {
      return s;
    }
  }
  h.stride_x = static_cast<double>(image.cols) / h.width;
  h.stride_y = static_cast<double>(image.rows) / h.height;
  return h;
}

}  // namespace semnav::relocalization
