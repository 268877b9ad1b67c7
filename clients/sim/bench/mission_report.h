// Mission benchmark outputs: JSON per strategy, a Markdown table, a console table.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "clients/sim/core/episode_metrics.h"

namespace semnav::sim::bench {

// Whether a record's strategy label is the exploration-only baseline (NEAREST_FRONTIER) that
// outdoor path lengths are compared against (seed 000).
bool IsExplorationOnly(const std::string& strategy_label);

// Targets of a recovery (issue 16): within 15 s of simulated time, 0.2 m and 3 deg off after it.
inline constexpr double kRecoveryTimeTargetS = 15.0;
inline constexpr double kRecoveryErrorTargetM = 0.2;
inline constexpr double kRecoveryErrorTargetDeg = 3.0;

// A pose-loss group's localization figures for one strategy, and its SR / SPL next to the same
// episodes (strategy, world, start, target) of the indoor group without drift.
struct PoseLossSummary {
  std::string strategy;
  int episodes = 0;
  int losses = 0;
  int recoveries = 0;
  int recovered_on_target = 0;          // recoveries within the time and error targets
  double median_recovery_time_s = 0.0;  // over recoveries; 0 when none
  double mean_recovery_error_m = 0.0;
  double mean_recovery_error_deg = 0.0;
  double mean_final_pose_error_m = 0.0;
  int paired = 0;                                          // episodes with an indoor twin
  double sr = 0.0, spl = 0.0;                              // over the paired episodes
  double sr_without_drift = 0.0, spl_without_drift = 0.0;  // their indoor twins
};
std::vector<PoseLossSummary> SummarisePoseLoss(const std::vector<EpisodeRecord>& group,
                                               const std::vector<EpisodeRecord>& indoor);

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
// Groups "drift" and "kidnapped" (pose loss) add "localization": {NAME: {episodes, losses,
// recoveries, recovered_on_target, recovered_on_target_share, median_recovery_time_s,
// mean_recovery_error_m, mean_recovery_error_deg, mean_final_pose_error_m, paired, sr, spl,
// sr_without_drift, spl_without_drift}}; episode rows add start_index, losses, recovery_times_s,
// recovery_errors_m, recovery_errors_deg, final_pose_error_m.
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
std::vector<SweepPoint> SweepSummary(const std::vector<EpisodeRecord>& records,
                                     const std::string& group, const std::string& strategy,
                                     const std::vector<double>& accuracies);

// One table per group (Markdown, also printed to the console) followed by its failed episodes
// by cause, then the strategies not run.
std::string MissionTable(const std::vector<EpisodeRecord>& records, double success_radius,
                         const NotRun& not_run = {});

}  // namespace semnav::sim::bench
