#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <string>

#include "absl/base/thread_annotations.h"
#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "services/relocalization/core/object_points.h"

namespace semnav::relocalization {

// A CenterNet-style ONNX detector: one image input, heads as named NCHW float outputs.
struct OnnxHeadsConfig {
  std::string model_path;  // .onnx file
  int input_width = 512;   // the image is resized to this before inference
  int input_height = 512;
  double pixel_scale = 1.0 / 255.0;                 // blob = (pixel - mean) * pixel_scale
  double mean_r = 0.0, mean_g = 0.0, mean_b = 0.0;  // per-channel mean, 0-255
  bool swap_rb = true;                              // feed RGB from OpenCV's BGR images
  std::string heatmap_output = "heatmap";           // [1, C, H, W] logits
  std::string offset_output = "offset";             // [1, 2, H, W]
  std::string size_output = "size";                 // [1, 2, H, W]
  std::string feature_output;                       // [1, F, H, W]; empty = no feature head
};

// Runs the detector with OpenCV DNN and returns its heads as HeadTensors whose strides
// map grid cells back to pixels of the image given to Run.
class OnnxHeads {
 public:
  // NOT_FOUND when the file is missing, INVALID_ARGUMENT when OpenCV cannot parse it.
  static absl::StatusOr<std::unique_ptr<OnnxHeads>> Load(const OnnxHeadsConfig& config);

  // `image` is 8-bit BGR. INVALID_ARGUMENT naming "image" when empty or of another type.
  absl::StatusOr<HeadTensors> Run(const cv::Mat& image);

 private:
  OnnxHeads(const OnnxHeadsConfig& config, cv::dnn::Net net)
      : config_(config), net_(std::move(net)) {}

  const OnnxHeadsConfig config_;
  absl::Mutex mu_;  // cv::dnn::Net::forward is not thread-safe
  cv::dnn::Net net_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::relocalization
