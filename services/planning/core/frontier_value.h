#pragma once

#include <optional>
#include <vector>

#include "services/planning/core/cell_grid.h"
#include "services/planning/core/frontier.h"
#include "services/planning/core/frontier_scoring.h"

namespace semnav::planning {

// SEMANTIC_FRONTIER's value map over frontiers (VLFM / ApexNav style, built from what is known
// rather than from image-text similarity). For frontier f:
//   evidence  V_f = max over objects o of w_o exp(-|c_f - o|^2 / (2 sigma^2)),
//                   w_o = max(relevance, relation, co-occurrence) of o with the target
//   gain      G_f = unexplored area (m^2) reachable from f through unexplored cells within
//                   gain_radius_m of its centroid (seen space and space behind known walls: 0)
//   utility   U_f = (1 + semantic_gain V_f) G_f exp(-distance_decay_per_m d_f)
// with d_f the path distance. Room first: frontiers whose centroids lie within region_link_m of
// each other (single linkage) form a region; the region with the best
//   U_r = (1 + semantic_gain max V) (max G) exp(-distance_decay_per_m min d)
// is chosen, then the frontier of best U_f inside it. Frontiers with G_f < min_gain_m2 (pockets
// the sensor has all but seen) are only taken when no other is reachable.
struct FrontierValueConfig {
  // Opt-in: on, the demo episode (SimLoopIntegrationTest.SearchEpisodeFindsTheCouchOutOfSight)
  // explores the far rooms first and runs out of budget; see docs/performance/mission.md.
  bool enabled = false;               // false: SEMANTIC_FRONTIER takes the best seed 002 total
  double evidence_sigma_m = 2.0;      // spread of an object's evidence: about half a room
  double semantic_gain = 2.0;         // a frontier at full evidence counts 3x the unknown area
  double gain_radius_m = 3.0;         // sensor range the gain is counted within
  double distance_decay_per_m = 0.2;  // Gonzalez-Banos & Latombe: U = G exp(-lambda C)
  double region_link_m = 3.0;         // seed 002's 3 m region clustering
  double min_gain_m2 = 0.25;          // one robot footprint
};

struct FrontierValue {
  double evidence = 0.0;  // V_f in [0, 1]
  double gain_m2 = 0.0;   // G_f
  double utility = 0.0;   // U_f (0 when unreachable)
  int region = -1;        // region index
};

// Values of `frontiers` (cells in the explored/free grids, `candidates` their centroids and path
// distances in metres, as ExtractFrontiers / BuildView give them).
std::vector<FrontierValue> ValueFrontiers(const std::vector<Frontier>& frontiers,
                                          const std::vector<FrontierCandidate>& candidates,
                                          const CellGrid<uint8_t>& explored, double resolution_m,
                                          const std::vector<ScoredObject>& objects,
                                          const FrontierValueConfig& config);

// The chosen frontier (region first, then inside it), or nullopt when none is reachable.
std::optional<int> SelectValuedFrontier(const std::vector<FrontierCandidate>& candidates,
                                        const std::vector<FrontierValue>& values,
                                        const FrontierValueConfig& config);

}  // namespace semnav::planning
