#include "services/relocalization/core/landmark.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"

namespace semnav::relocalization {

int DescriptorLabel(const Descriptor& descriptor) {
  int best = -1;
  for (size_t i = 0; i < descriptor.size(); ++i) {
    if (best < 0 || descriptor[i] > descriptor[static_cast<size_t>(best)]) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

std::vector<int> TopDescriptorLabels(const Descriptor& descriptor, size_t count) {
  std::vector<int> labels(descriptor.size());
  for (size_t i = 0; i < labels.size(); ++i) labels[i] = static_cast<int>(i);
  const size_t keep = std::min(count, labels.size());
  std::partial_sort(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(keep),
                    labels.end(), [&](int a, int b) {
                      const float va = descriptor[static_cast<size_t>(a)];
                      const float vb = descriptor[static_cast<size_t>(b)];
                      return va > vb || (va == vb && a < b);
                    });
  labels.resize(keep);
  return labels;
}

double CosineSimilarity(const Descriptor& a, const Descriptor& b) {
  const size_t n = std::min(a.size(), b.size());
  double dot = 0.0, na = 0.0, nb = 0.0;
  for (size_t i = 0; i < n; ++i) {
    dot += static_cast<double>(a[i]) * b[i];
    na += static_cast<double>(a[i]) * a[i];
    nb += static_cast<double>(b[i]) * b[i];
  }
  if (na <= 0.0 || nb <= 0.0) return 0.0;
  return dot / std::sqrt(na * nb);
}

absl::Status ValidateLandmark(const Landmark& landmark, size_t descriptor_dim,
                              absl::string_view field) {
  const Eigen::Vector3d& p = landmark.position;
  if (auto s = CheckPoint(p.x(), p.y(), p.z(), absl::StrCat(field, ".position"), kMaxCoordinateM);
      !s.ok()) {
    return s;
  }
  const std::string scale_field = absl::StrCat(field, ".scale_m");
  if (auto s = CheckRange(landmark.scale, scale_field, 0.0, kMaxLandmarkScaleM); !s.ok()) return s;
  if (landmark.scale <= 0.0) return InvalidField(scale_field, "must be > 0");
  if (landmark.observations > kMaxObservations) {
    return InvalidField(absl::StrCat(field, ".observations"),
                        absl::StrCat("must be at most ", kMaxObservations));
  }
  const std::string embedding = absl::StrCat(field, ".embedding");
  if (landmark.descriptor.empty()) return InvalidField(embedding, "must not be empty");
  if (auto s = CheckCount(landmark.descriptor.size(), embedding, kMaxDescriptorDim); !s.ok()) {
    return s;
  }
  if (descriptor_dim != 0 && landmark.descriptor.size() != descriptor_dim) {
    return InvalidField(embedding, absl::StrCat("length ", landmark.descriptor.size(),
                                                " != map descriptor length ", descriptor_dim));
  }
  for (size_t i = 0; i < landmark.descriptor.size(); ++i) {
    const float v = landmark.descriptor[i];
    if (!std::isfinite(v) || std::abs(v) > kMaxDescriptorValue) {
      return InvalidField(embedding, absl::StrCat("entry ", i, " must be finite and within +-",
                                                  kMaxDescriptorValue));
    }
  }
  return absl::OkStatus();
}

}  // namespace semnav::relocalization
