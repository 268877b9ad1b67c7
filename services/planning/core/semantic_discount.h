// SEMANTIC_FRONTIER's opt-in choice, per platform (`semantic_discount.platforms`, default none):
// the nearest frontier, with its path cost discounted by the semantic evidence of seed 002's terms
// (language and the three grounding signals). ApexNav's lesson, in one rule: where the evidence is
// flat the search is the nearest-frontier search (a robot that knows nothing explores near first),
// and only evidence that differs between frontiers pulls the robot further. On the hold-out
// hand-drawn worlds it lifts SR / SPL from 0.333 / 0.102 to 0.583 / 0.234, but it loses on the
// generated indoor suite (SR 0.875 -> 0.800; with the glance 0.825 -> 0.800) and more for robots
// that fly (outdoor SR 1.000 -> 0.533: short hops to the nearest cells of frontiers that a wide
// view reveals at once). So it is off by default; docs/performance/mission.md, "Semantic
// discount" and "Glance and the discount per platform".
//   evidence  S_f = max(language_f, gradient_f, relation_f, co-occurrence_f), the strongest cue
//             (a weighted mean halved a lone co-occurrence, the usual cue, and left it no pull)
//   utility   U_f = (1 + gain S_f) / (d_f + offset_m)
// with d_f the path distance to the frontier's nearest cell; the highest U_f wins (ties: nearer).
#pragma once

#include <optional>
#include <vector>

#include "services/planning/core/frontier_scoring.h"

namespace semnav::planning {

// How the robot moves and sees (the request's platform).
enum class ExplorationPlatform { kUnspecified, kGround, kAerial };

struct SemanticDiscountConfig {
  // The platforms that take the discount; the others take the best seed 002 total.
  bool ground = false;
  bool aerial = false;
  bool unspecified = false;  // requests that do not say (clients from before the field)
  double gain = 2.0;         // full evidence makes a frontier worth (1 + gain) times its path cost
  double offset_m = 1.0;     // keeps frontiers at the robot's feet from dwarfing all evidence
};

bool DiscountApplies(const SemanticDiscountConfig& config, ExplorationPlatform platform);

// S_f in [0, 1]: the strongest of the seed 002 semantic signals.
double SemanticEvidence(const FrontierScore& score);

// The chosen frontier among the reachable candidates (path_distance_m >= 0); nullopt when none.
std::optional<int> SelectDiscountedFrontier(const std::vector<FrontierCandidate>& candidates,
                                            const std::vector<FrontierScore>& scores,
                                            const SemanticDiscountConfig& config);

}  // namespace semnav::planning
