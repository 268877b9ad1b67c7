#include "services/relocalization/core/landmark.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"

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
  if (!landmark.position.allFinite()) {
    return absl::InvalidArgumentError(absl::StrCat(field, ".position: must be finite"));
  }
  if (!std::isfinite(landmark.scale) || landmark.scale <= 0.0) {
    return absl::InvalidArgumentError(
        absl::StrCat(field, ".scale: must be finite and > 0, got ", landmark.scale));
  }
  if (landmark.descriptor.empty()) {
    return absl::InvalidArgumentError(absl::StrCat(field, ".embedding: must not be empty"));
  }
  if (descriptor_dim != 0 && landmark.descriptor.size() != descriptor_dim) {
    return absl::InvalidArgumentError(absl::StrCat(field, ".embedding: length ",
                                                   landmark.descriptor.size(),
                                                   " != map descriptor length ", descriptor_dim));
  }
  for (float v : landmark.descriptor) {
    if (!std::isfinite(v)) {
      return absl::InvalidArgumentError(absl::StrCat(field, ".embedding: must be finite"));
    }
  }
  return absl::OkStatus();
}

}  // namespace semnav::relocalization
