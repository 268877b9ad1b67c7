#include "services/relocalization/core/object_points.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/string_view.h"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"

namespace semnav::relocalization {
namespace {

double Sigmoid(double x) { return 1.0 / (1.0 + std::exp(-x)); }

absl::Status CheckPlane(const std::vector<float>& data, size_t channels, size_t cells,
                        absl::string_view name) {
  if (data.size() != channels * cells) {
    return InvalidField(absl::StrCat("tensors.", name),
                        absl::StrCat("expected ", channels * cells, " values, got ", data.size()));
  }
  for (float v : data) {
    if (!std::isfinite(v)) {
      return InvalidField(absl::StrCat("tensors.", name), "must be finite");
    }
  }
  return absl::OkStatus();
}

// Bounds keep channels x cells far from size_t overflow (2^15 x 2^15 x 2^16 = 2^46).
constexpr int kMaxSide = 1 << 15;
constexpr int kMaxChannels = 1 << 16;
constexpr double kMaxStride = 1024.0;

absl::Status Validate(const HeadTensors& h, const ObjectPointParams& p) {
  if (auto s = CheckRange(h.width, "tensors.width", 1, kMaxSide); !s.ok()) return s;
  if (auto s = CheckRange(h.height, "tensors.height", 1, kMaxSide); !s.ok()) return s;
  if (auto s = CheckRange(h.heatmap_channels, "tensors.heatmap_channels", 1, kMaxChannels);
      !s.ok()) {
    return s;
  }
  if (auto s = CheckRange(h.feature_channels, "tensors.feature_channels", 0, kMaxChannels);
      !s.ok()) {
    return s;
  }
  // A stride maps cells to pixels: beyond kMaxStride the boxes leave any real image.
  if (auto s = CheckRange(h.stride_x, "tensors.stride_x", 0.0, kMaxStride); !s.ok()) return s;
  if (auto s = CheckRange(h.stride_y, "tensors.stride_y", 0.0, kMaxStride); !s.ok()) return s;
  if (h.stride_x <= 0.0) return InvalidField("tensors.stride_x", "must be > 0");
  if (h.stride_y <= 0.0) return InvalidField("tensors.stride_y", "must be > 0");
  if (p.top_k <= 0) return InvalidField("top_k", "must be > 0");
  if (p.nms_kernel < 0) return InvalidField("params", "nms_kernel must be >= 0");
  const size_t cells = static_cast<size_t>(h.width) * static_cast<size_t>(h.height);
  if (auto s = CheckPlane(h.heatmap, static_cast<size_t>(h.heatmap_channels), cells, "heatmap");
      !s.ok()) {
    return s;
  }
  if (auto s = CheckPlane(h.offset, 2, cells, "offset"); !s.ok()) return s;
  if (auto s = CheckPlane(h.size, 2, cells, "box_size"); !s.ok()) return s;
  return CheckPlane(h.features, static_cast<size_t>(h.feature_channels), cells, "features");
}

// M_wh = sigmoid(sum_c H_whc) (seed 001, 2.2, first equation).
std::vector<double> GeneralizedConfidence(const HeadTensors& h) {
  const size_t cells = static_cast<size_t>(h.width) * static_cast<size_t>(h.height);
  std::vector<double> m(cells, 0.0);
  for (int c = 0; c < h.heatmap_channels; ++c) {
    const float* plane = h.heatmap.data() + static_cast<size_t>(c) * cells;
    for (size_t i = 0; i < cells; ++i) m[i] += plane[i];
  }
  for (double& v : m) v = Sigmoid(v);
  return m;
}

// A cell survives max-pool NMS when it equals the maximum of its (2k+1)^2 window.
bool IsPoolPeak(const std::vector<double>& m, int w, int h, int x, int y, int k) {
  const double centre = m[static_cast<size_t>(y) * w + x];
  for (int j = std::max(0, y - k); j <= std::min(h - 1, y + k); ++j) {
    for (int i = std::max(0, x - k); i <= std::min(w - 1, x + k); ++i) {
      if (m[static_cast<size_t>(j) * w + i] > centre) return false;
    }
  }
  return true;
}

ObjectPoint MakePoint(const HeadTensors& h, size_t cell, double score) {
  const size_t cells = static_cast<size_t>(h.width) * static_cast<size_t>(h.height);
  const int x = static_cast<int>(cell % static_cast<size_t>(h.width));
  const int y = static_cast<int>(cell / static_cast<size_t>(h.width));
  ObjectPoint p;
  p.score = score;
  p.u = (x + h.offset[cell]) * h.stride_x;
  p.v = (y + h.offset[cells + cell]) * h.stride_y;
  const double half_w = 0.5 * h.size[cell] * h.stride_x;
  const double half_h = 0.5 * h.size[cells + cell] * h.stride_y;
  p.box = {p.u - half_w, p.v - half_h, p.u + half_w, p.v + half_h};
  if (h.feature_channels > 0) {
    for (int c = 0; c < h.feature_channels; ++c) {
      p.descriptor.push_back(h.features[static_cast<size_t>(c) * cells + cell]);
    }
  } else {
    for (int c = 0; c < h.heatmap_channels; ++c) {
      p.descriptor.push_back(
          static_cast<float>(Sigmoid(h.heatmap[static_cast<size_t>(c) * cells + cell])));
    }
  }
  return p;
}

}  // namespace

double BoxIou(const PixelBox& a, const PixelBox& b) {
  const double area_a = std::max(0.0, a.x1 - a.x0) * std::max(0.0, a.y1 - a.y0);
  const double area_b = std::max(0.0, b.x1 - b.x0) * std::max(0.0, b.y1 - b.y0);
  if (area_a <= 0.0 || area_b <= 0.0) return 0.0;
  const double iw = std::max(0.0, std::min(a.x1, b.x1) - std::max(a.x0, b.x0));
  const double ih = std::max(0.0, std::min(a.y1, b.y1) - std::max(a.y0, b.y0));
  const double inter = iw * ih;
  return inter / (area_a + area_b - inter);
}

absl::StatusOr<std::vector<ObjectPoint>> ExtractObjectPoints(const HeadTensors& heads,
                                                             const ObjectPointParams& params) {
  if (auto s = Validate(heads, params); !s.ok()) return s;
  const std::vector<double> m = GeneralizedConfidence(heads);

  std::vector<size_t> peaks;
  for (int y = 0; y < heads.height; ++y) {
    for (int x = 0; x < heads.width; ++x) {
      if (IsPoolPeak(m, heads.width, heads.height, x, y, params.nms_kernel)) {
        peaks.push_back(static_cast<size_t>(y) * heads.width + x);
      }
    }
  }
  const size_t keep = std::min(peaks.size(), static_cast<size_t>(params.top_k));
  std::partial_sort(peaks.begin(), peaks.begin() + static_cast<std::ptrdiff_t>(keep), peaks.end(),
                    [&](size_t a, size_t b) { return m[a] > m[b] || (m[a] == m[b] && a < b); });
  peaks.resize(keep);

  std::vector<ObjectPoint> kept;
  for (size_t cell : peaks) {
    ObjectPoint candidate = MakePoint(heads, cell, m[cell]);
    const bool duplicate = std::any_of(kept.begin(), kept.end(), [&](const ObjectPoint& k) {
      return BoxIou(k.box, candidate.box) > params.box_iou_threshold;
    });
    if (!duplicate) kept.push_back(std::move(candidate));
  }
  return kept;
}

}  // namespace semnav::relocalization
