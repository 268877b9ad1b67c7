#include "services/relocalization/core/similarity.h"

#include <algorithm>
#include <cmath>

namespace semnav::relocalization {

double PositionSimilarity(double error_m, double sigma_m) {
  return std::exp(-(error_m * error_m) / (2.0 * sigma_m * sigma_m));
}

double ScaleSimilarity(double scale_a, double scale_b) {
  if (scale_a <= 0.0 || scale_b <= 0.0) return 0.0;
  return std::min(scale_a, scale_b) / std::max(scale_a, scale_b);
}

double ScaleTolerance(const SimilarityParams& params, double scale_a, double scale_b) {
  if (params.pos_sigma_per_scale <= 0.0) return 1.0;
  const double extra = params.pos_sigma_per_scale * std::max(scale_a, scale_b) / params.pos_sigma_m;
  return std::sqrt(1.0 + extra * extra);
}

double CombinedSimilarity(const SimilarityTerms& terms, const SimilarityParams& params) {
  if (terms.pos <= params.pos_threshold || terms.scale <= params.scale_threshold ||
      terms.desc <= params.desc_threshold) {
    return 0.0;
  }
  return params.alpha * terms.pos + params.beta * terms.scale + params.gamma * terms.desc;
}

}  // namespace semnav::relocalization
