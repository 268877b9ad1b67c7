#include "services/planning/core/semantic_discount.h"

#include <algorithm>

namespace semnav::planning {

bool DiscountApplies(const SemanticDiscountConfig& config, ExplorationPlatform platform) {
  switch (platform) {
    case ExplorationPlatform::kGround:
      return config.ground;
    case ExplorationPlatform::kAerial:
      return config.aerial;
    case ExplorationPlatform::kUnspecified:
      return config.unspecified;
  }
  return false;
}

double SemanticEvidence(const FrontierScore& score) {
  return std::clamp(std::max({score.language, score.gradient, score.relation, score.cooccurrence}),
                    0.0, 1.0);
}

std::optional<int> SelectDiscountedFrontier(const std::vector<FrontierCandidate>& candidates,
                                            const std::vector<FrontierScore>& scores,
                                            const SemanticDiscountConfig& config) {
  std::optional<int> best;
  double best_utility = 0.0;
  for (size_t i = 0; i < candidates.size() && i < scores.size(); ++i) {
    const double d = candidates[i].path_distance_m;
    if (d < 0.0) continue;
    const double utility =
        (1.0 + config.gain * SemanticEvidence(scores[i])) / (d + config.offset_m);
    if (!best || utility > best_utility ||
        (utility == best_utility && d < candidates[*best].path_distance_m)) {
      best = static_cast<int>(i);
      best_utility = utility;
    }
  }
  return best;
}

}  // namespace semnav::planning
