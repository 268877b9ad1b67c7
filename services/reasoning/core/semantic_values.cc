#include "services/reasoning/core/semantic_values.h"

#include <algorithm>

namespace semnav::reasoning {

SemanticValues::SemanticValues(int eroi_count)
    : prior_(1.0 / std::max(1, eroi_count)),
      values_(static_cast<std::size_t>(std::max(1, eroi_count)), prior_) {}

void SemanticValues::ApplyVlmEvidence(const std::vector<int>& neighbourhood) {
  if (neighbourhood.empty()) return;
  const double weight = 1.0 / static_cast<double>(neighbourhood.size());  // (C/5)/m with C = 5
  for (int eroi : neighbourhood) {
    double& s = values_[static_cast<std::size_t>(eroi)];
    s = (1.0 - weight) * s + weight;
  }
}

void SemanticValues::ApplyRegionScore(const std::vector<int>& region, int score) {
  if (region.empty()) return;
  const double k = static_cast<double>(region.size());
  const double sr = std::clamp(score, -5, 5);
  for (int eroi : region) {
    double& s = values_[static_cast<std::size_t>(eroi)];
    if (sr <= 0.0) {
      s = prior_ + (s - prior_) * (sr / 5.0 + 1.0) / k;
    } else {
      s = s + (1.0 - s) * sr / (5.0 * k);
    }
    s = std::max(s, prior_);
  }
}

}  // namespace semnav::reasoning
