#pragma once

#include <vector>

#include "absl/status/statusor.h"
#include "services/relocalization/core/landmark.h"

namespace semnav::relocalization {

// Detector heads of a CenterNet-style network (seed 001, 2.1), planar CHW float
// layout over a width x height grid. One grid cell covers stride_x x stride_y image pixels.
struct HeadTensors {
  int width = 0;
  int height = 0;
  int heatmap_channels = 0;
  std::vector<float> heatmap;   // heatmap_channels x height x width, logits
  std::vector<float> offset;    // 2 x height x width: sub-cell offset (du, dv), cells
  std::vector<float> size;      // 2 x height x width: box (width, height), cells
  int feature_channels = 0;     // 0 = no feature head
  std::vector<float> features;  // feature_channels x height x width
  double stride_x = 1.0;        // image pixels per grid cell, horizontally
  double stride_y = 1.0;        // image pixels per grid cell, vertically
};

// Axis-aligned box in image pixels.
struct PixelBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// A generalized object point (seed 001, 2.2): q = {u, v, p} plus its box and descriptor.
struct ObjectPoint {
  double u = 0.0;  // image pixels, box centre
  double v = 0.0;
  double score = 0.0;  // sigmoid of the channel-summed heatmap
  PixelBox box;
  Descriptor descriptor;  // feature vector at the peak, else per-channel sigmoid
};

// Inference-head parameters (seed 001, 2.2).
struct ObjectPointParams {
  int nms_kernel = 1;              // k: max-pool window is (2k+1) x (2k+1) cells
  int top_k = 100;                 // points kept from the pooled heatmap
  double box_iou_threshold = 0.5;  // final suppression: drop a box overlapping a kept one more
};

// Sum channels -> sigmoid -> max-pool NMS -> top-k -> boxes -> IoU suppression.
// Malformed tensors -> INVALID_ARGUMENT naming the tensor.
absl::StatusOr<std::vector<ObjectPoint>> ExtractObjectPoints(const HeadTensors& heads,
                                                             const ObjectPointParams& params);

// Intersection over union of two boxes; 0 when either has no area.
double BoxIou(const PixelBox& a, const PixelBox& b);

}  // namespace semnav::relocalization
