// SEMANTIC_FRONTIER's default choice: the nearest frontier, with its path cost discounted by the
// semantic evidence of seed 002's terms (language and the three grounding signals). ApexNav's
// lesson, in one rule: where the evidence is flat the search is the nearest-frontier search (a
// robot that knows nothing explores near first), and only evidence that differs between frontiers
// pulls the robot further. The seed's full total (with its 0.2 normalised distance and 0.3 novelty
// terms) hopped to far frontiers and left the near ones for later: 0.069 SPL against
// nearest-frontier's 0.183 on the hold-out hand-drawn worlds (docs/performance/mission.md).
//   evidence  S_f = max(language_f, gradient_f, relation_f, co-occurrence_f), the strongest cue
//             (a weighted mean halved a lone co-occurrence, the usual cue, and left it no pull)
//   utility   U_f = (1 + gain S_f) / (d_f + offset_m)
// with d_f the path distance to the frontier's nearest cell; the highest U_f wins (ties: nearer).
#pragma once

#include <optional>
#include <vector>

#include "services/planning/core/frontier_scoring.h"

namespace semnav::planning {

struct SemanticDiscountConfig {
  bool enabled = true;    // false: the best seed 002 total
  double gain = 2.0;      // full evidence makes a frontier worth (1 + gain) times its path cost
  double offset_m = 1.0;  // keeps frontiers at the robot's feet from dwarfing all evidence
};

// S_f in [0, 1]: the strongest of the seed 002 semantic signals.
double SemanticEvidence(const FrontierScore& score);

// The chosen frontier among the reachable candidates (path_distance_m >= 0); nullopt when none.
std::optional<int> SelectDiscountedFrontier(const std::vector<FrontierCandidate>& candidates,
                                            const std::vector<FrontierScore>& scores,
                                            const SemanticDiscountConfig& config);

}  // namespace semnav::planning
