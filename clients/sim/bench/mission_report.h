// Mission benchmark outputs: JSON per strategy, a Markdown table, a console table.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "clients/sim/core/episode_metrics.h"

namespace semnav::sim::bench {

// The exploration-only baseline outdoor path lengths are compared against (seed 000).
inline constexpr char kExplorationOnly[] = "NEAREST_FRONTIER";

// Strategies asked for but not run, with the reason (e.g. EROI_UTILITY without a model).
using NotRun = std::map<std::string, std::string>;

// {"success_radius_m": r,
//  "strategies": {NAME: {sr, spl, dtg, path_m, time_s, model_calls, model_tokens,
//                        model_wait_s (simulated s), vision_calls, fast_path_share, episodes,
//                        failures: {CAUSE: n}}},
//      (the indoor group, the headline)
//  "groups": {GROUP: {"strategies": {NAME: {the same keys}}, "energy_j": {NAME: mean},
//             "path_vs_exploration_only": {NAME: mean path / NEAREST_FRONTIER's mean path},
//             "path_vs_exploration_only_both_found": {NAME: {ratio, episodes}}: path sums over the
//             episodes both found the target (seed 000's comparison: all its methods succeeded)}},
//  "not_run": {NAME: reason}, "episodes": [per-episode rows]}.
absl::Status WriteMissionJson(const std::vector<EpisodeRecord>& records, double success_radius,
                              const NotRun& not_run, const std::string& path);
// One table per group (Markdown, also printed to the console) followed by its failed episodes
// by cause, then the strategies not run.
std::string MissionTable(const std::vector<EpisodeRecord>& records, double success_radius,
                         const NotRun& not_run = {});

}  // namespace semnav::sim::bench
