// Mission benchmark outputs: JSON per strategy, a Markdown table, a console table.
#pragma once

#include <map>
#include <optional>
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
// The VLM-quality sweep (issue 15): the strategy runs once per recognition accuracy, its records
// labelled SweepLabel(strategy, accuracy), e.g. "EROI_UTILITY@0.70", beside the baselines.
std::string SweepLabel(const std::string& strategy, double accuracy);
struct SweepPoint {
  double accuracy = 0.0;
  int episodes = 0;
  double sr = 0.0;
  // Path over the exploration-only baseline's on the episodes both found (seed 000); unset when
  // none did.
  std::optional<double> path_ratio;
  int paired_episodes = 0;
  // Mean path over the baseline's mean path on all episodes (unset without the baseline): the
  // only path figure when the baseline found nothing.
  std::optional<double> mean_path_ratio;
  double vision_calls = 0.0;  // mean per episode
  double model_calls = 0.0;   // mean per episode
};
// One point per accuracy (in the order given) from the records of `group`.
std::vector<SweepPoint> SweepSummary(const std::vector<EpisodeRecord>& records, const std::string& group,
                                     const std::string& strategy, const std::vector<double>& accuracies);

// One table per group (Markdown, also printed to the console) followed by its failed episodes
// by cause, then the strategies not run.
std::string MissionTable(const std::vector<EpisodeRecord>& records, double success_radius,
                         const NotRun& not_run = {});

}  // namespace semnav::sim::bench
