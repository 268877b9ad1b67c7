#include "clients/sim/bench/mission_report.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "clients/sim/loop/episode_runner.h"

namespace semnav::sim::bench {
namespace {

constexpr const char* kGroups[] = {"indoor", "outdoor", "flyroll", "drift", "kidnapped"};

bool PoseLossGroup(const std::string& group) { return group == "drift" || group == "kidnapped"; }

nlohmann::json PoseLossJson(const PoseLossSummary& s) {
  return {{"episodes", s.episodes},
          {"losses", s.losses},
          {"recoveries", s.recoveries},
          {"recovered_on_target", s.recovered_on_target},
          {"recovered_on_target_share",
           s.losses > 0 ? static_cast<double>(s.recovered_on_target) / s.losses : 0.0},
          {"median_recovery_time_s", s.median_recovery_time_s},
          {"mean_recovery_error_m", s.mean_recovery_error_m},
          {"mean_recovery_error_deg", s.mean_recovery_error_deg},
          {"mean_final_pose_error_m", s.mean_final_pose_error_m},
          {"paired", s.paired},
          {"sr", s.sr},
          {"spl", s.spl},
          {"sr_without_drift", s.sr_without_drift},
          {"spl_without_drift", s.spl_without_drift}};
}

std::string PoseLossTable(const std::vector<PoseLossSummary>& summaries) {
  std::string table = absl::StrFormat(
      "\nLocalization (a recovery on target: within %.0f s, %.1f m and %.0f deg):\n\n"
      "| strategy | episodes | losses | recoveries | on target | median time (s) | error after (m "
      "/ deg) | "
      "final error (m) | SR / SPL | same episodes without drift: SR / SPL (episodes) |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n",
      kRecoveryTimeTargetS, kRecoveryErrorTargetM, kRecoveryErrorTargetDeg);
  for (const PoseLossSummary& s : summaries) {
    absl::StrAppend(
        &table,
        absl::StrFormat("| %s | %d | %d | %d | %d | %.1f | %.2f / %.1f | %.2f | %.3f / %.3f | "
                        "%.3f / %.3f (%d) |\n",
                        s.strategy, s.episodes, s.losses, s.recoveries, s.recovered_on_target,
                        s.median_recovery_time_s, s.mean_recovery_error_m,
                        s.mean_recovery_error_deg, s.mean_final_pose_error_m, s.sr, s.spl,
                        s.sr_without_drift, s.spl_without_drift, s.paired));
  }
  return table;
}

std::vector<EpisodeRecord> InGroup(const std::vector<EpisodeRecord>& records,
                                   const std::string& group) {
  std::vector<EpisodeRecord> out;
  for (const EpisodeRecord& r : records) {
    if (r.group == group) out.push_back(r);
  }
  return out;
}

}  // namespace

bool IsExplorationOnly(const std::string& strategy_label) {
  return loop::RequestedStrategy(strategy_label) ==
         reasoning::v1::EXPLORATION_STRATEGY_NEAREST_FRONTIER;
}

namespace {

// Mean path of `strategy` over mean path of the exploration-only baseline on the same episodes.
std::optional<double> PathVsExplorationOnly(const std::vector<StrategySummary>& summaries,
                                            const StrategySummary& s) {
  for (const StrategySummary& base : summaries) {
    if (IsExplorationOnly(base.strategy) && base.path_m > 0) return s.path_m / base.path_m;
  }
  return std::nullopt;
}

// Seed 000 compares paths of searches that all found the target. Sum of `strategy`'s paths over
// the baseline's on the episodes both succeeded; records pair by order within the group (every
// strategy runs the same episode plan). nullopt when no episode qualifies.
struct PairedRatio {
  double ratio = 0.0;
  int episodes = 0;
};
std::optional<PairedRatio> PathVsExplorationOnlyBothFound(const std::vector<EpisodeRecord>& group,
                                                          const std::string& strategy) {
  std::vector<const EpisodeRecord*> base, mine;
  for (const EpisodeRecord& r : group) {
    if (IsExplorationOnly(r.strategy)) base.push_back(&r);
    if (r.strategy == strategy) mine.push_back(&r);
  }
  PairedRatio paired;
  double base_sum = 0.0, mine_sum = 0.0;
  for (size_t i = 0; i < std::min(base.size(), mine.size()); ++i) {
    if (!base[i]->success || !mine[i]->success) continue;
    base_sum += base[i]->path_m;
    mine_sum += mine[i]->path_m;
    ++paired.episodes;
  }
  if (paired.episodes == 0 || base_sum <= 0.0) return std::nullopt;
  paired.ratio = mine_sum / base_sum;
  return paired;
}

nlohmann::json StrategyJson(const StrategySummary& s) {
  nlohmann::json failures = nlohmann::json::object();
  for (const auto& [cause, n] : s.failures) failures[cause] = n;
  return {{"sr", s.sr},
          {"spl", s.spl},
          {"dtg", s.dtg_m},
          {"path_m", s.path_m},
          {"time_s", s.time_s},
          {"model_calls", s.model_calls},
          {"model_tokens", s.model_tokens},
          {"model_wait_s", s.model_wait_s},
          {"vision_calls", s.vision_calls},
          {"fast_path_share", s.fast_path_share},
          {"episodes", s.episodes},
          {"failures", failures}};
}

// Per group, failed episodes by cause: one row per strategy, one column per cause seen in the
// group (sorted by name).
std::string FailureTable(const std::vector<StrategySummary>& summaries) {
  std::set<std::string> causes;
  for (const StrategySummary& s : summaries) {
    for (const auto& [cause, n] : s.failures) causes.insert(cause);
  }
  if (causes.empty()) return "";
  std::string table = "\nFailures by cause (episodes):\n\n| strategy | failed |";
  for (const std::string& cause : causes) absl::StrAppend(&table, " ", cause, " |");
  absl::StrAppend(&table, "\n|---|---|");
  for (size_t i = 0; i < causes.size(); ++i) absl::StrAppend(&table, "---|");
  absl::StrAppend(&table, "\n");
  for (const StrategySummary& s : summaries) {
    int failed = 0;
    for (const auto& [cause, n] : s.failures) failed += n;
    absl::StrAppend(&table, "| ", s.strategy, " | ", failed, " |");
    for (const std::string& cause : causes) {
      const auto it = s.failures.find(cause);
      absl::StrAppend(&table, " ", it == s.failures.end() ? 0 : it->second, " |");
    }
    absl::StrAppend(&table, "\n");
  }
  return table;
}

}  // namespace

std::string SweepLabel(const std::string& strategy, double accuracy) {
  return absl::StrFormat("%s@%.2f", strategy, accuracy);
}

std::vector<SweepPoint> SweepSummary(const std::vector<EpisodeRecord>& records,
                                     const std::string& group, const std::string& strategy,
                                     const std::vector<double>& accuracies) {
  const std::vector<EpisodeRecord> in_group = InGroup(records, group);
  const std::vector<StrategySummary> summaries = SummariseByStrategy(in_group);
  std::vector<SweepPoint> points;
  for (double accuracy : accuracies) {
    const std::string label = SweepLabel(strategy, accuracy);
    SweepPoint point;
    point.accuracy = accuracy;
    for (const StrategySummary& s : summaries) {
      if (s.strategy != label) continue;
      point.episodes = s.episodes;
      point.sr = s.sr;
      point.vision_calls = s.vision_calls;
      point.model_calls = s.model_calls;
      point.mean_path_ratio = PathVsExplorationOnly(summaries, s);
    }
    if (const std::optional<PairedRatio> paired = PathVsExplorationOnlyBothFound(in_group, label)) {
      point.path_ratio = paired->ratio;
      point.paired_episodes = paired->episodes;
    }
    points.push_back(point);
  }
  return points;
}

std::vector<PoseLossSummary> SummarisePoseLoss(const std::vector<EpisodeRecord>& group,
                                               const std::vector<EpisodeRecord>& indoor) {
  std::vector<PoseLossSummary> out;
  std::map<std::string, std::vector<double>> times;
  for (const EpisodeRecord& r : group) {
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const PoseLossSummary& s) { return s.strategy == r.strategy; });
    if (it == out.end()) {
      out.emplace_back();
      out.back().strategy = r.strategy;
      it = out.end() - 1;
    }
    PoseLossSummary& s = *it;
    ++s.episodes;
    s.losses += r.losses;
    for (size_t k = 0; k < r.recovery_times_s.size(); ++k) {
      ++s.recoveries;
      times[r.strategy].push_back(r.recovery_times_s[k]);
      s.mean_recovery_error_m += r.recovery_errors_m[k];
      s.mean_recovery_error_deg += r.recovery_errors_deg[k];
      if (r.recovery_times_s[k] <= kRecoveryTimeTargetS &&
          r.recovery_errors_m[k] <= kRecoveryErrorTargetM &&
          r.recovery_errors_deg[k] <= kRecoveryErrorTargetDeg) {
        ++s.recovered_on_target;
      }
    }
    s.mean_final_pose_error_m += r.final_pose_error_m;
    // The indoor twin: same strategy, world, start and target.
    for (const EpisodeRecord& twin : indoor) {
      if (twin.strategy != r.strategy || twin.world != r.world ||
          twin.start_index != r.start_index || twin.target != r.target) {
        continue;
      }
      ++s.paired;
      s.sr += r.success ? 1.0 : 0.0;
      s.spl += SuccessWeightedPathLength(r.success, r.shortest_path_m, r.path_m);
      s.sr_without_drift += twin.success ? 1.0 : 0.0;
      s.spl_without_drift +=
          SuccessWeightedPathLength(twin.success, twin.shortest_path_m, twin.path_m);
      break;
    }
  }
  for (PoseLossSummary& s : out) {
    std::vector<double>& t = times[s.strategy];
    if (!t.empty()) {
      std::sort(t.begin(), t.end());
      s.median_recovery_time_s =
          t.size() % 2 == 1 ? t[t.size() / 2] : 0.5 * (t[t.size() / 2 - 1] + t[t.size() / 2]);
      s.mean_recovery_error_m /= static_cast<double>(t.size());
      s.mean_recovery_error_deg /= static_cast<double>(t.size());
    }
    s.mean_final_pose_error_m /= std::max(1, s.episodes);
    if (s.paired > 0) {
      for (double* mean : {&s.sr, &s.spl, &s.sr_without_drift, &s.spl_without_drift})
        *mean /= s.paired;
    }
  }
  return out;
}

absl::Status WriteMissionJson(const std::vector<EpisodeRecord>& records, double success_radius,
                              const NotRun& not_run, const std::string& path) {
  nlohmann::json out;
  out["success_radius_m"] = success_radius;
  out["strategies"] = nlohmann::json::object();
  out["groups"] = nlohmann::json::object();
  for (const char* group : kGroups) {
    const std::vector<StrategySummary> summaries = SummariseByStrategy(InGroup(records, group));
    if (summaries.empty()) continue;
    nlohmann::json strategies = nlohmann::json::object();
    nlohmann::json energy = nlohmann::json::object();
    nlohmann::json ratio = nlohmann::json::object();
    nlohmann::json both_found = nlohmann::json::object();
    const std::vector<EpisodeRecord> in_group = InGroup(records, group);
    for (const StrategySummary& s : summaries) {
      strategies[s.strategy] = StrategyJson(s);
      energy[s.strategy] = s.energy_j;
      if (const std::optional<double> r = PathVsExplorationOnly(summaries, s))
        ratio[s.strategy] = *r;
      if (const std::optional<PairedRatio> p =
              PathVsExplorationOnlyBothFound(in_group, s.strategy)) {
        both_found[s.strategy] = {{"ratio", p->ratio}, {"episodes", p->episodes}};
      }
    }
    out["groups"][group] = {{"strategies", strategies},
                            {"energy_j", energy},
                            {"path_vs_exploration_only", ratio},
                            {"path_vs_exploration_only_both_found", both_found}};
    if (PoseLossGroup(group)) {
      nlohmann::json localization = nlohmann::json::object();
      for (const PoseLossSummary& s : SummarisePoseLoss(in_group, InGroup(records, "indoor"))) {
        localization[s.strategy] = PoseLossJson(s);
      }
      out["groups"][group]["localization"] = localization;
    }
    if (std::string(group) == "indoor") out["strategies"] = strategies;
  }
  out["not_run"] = nlohmann::json::object();
  for (const auto& [strategy, reason] : not_run) out["not_run"][strategy] = reason;
  nlohmann::json rows = nlohmann::json::array();
  for (const EpisodeRecord& r : records) {
    rows.push_back({{"strategy", r.strategy},
                    {"group", r.group},
                    {"world", r.world},
                    {"target", r.target},
                    {"success", r.success},
                    {"shortest_path_m", r.shortest_path_m},
                    {"path_m", r.path_m},
                    {"dtg_m", r.distance_to_goal_m},
                    {"time_s", r.time_s},
                    {"energy_j", r.energy_j},
                    {"model_calls", r.model_calls},
                    {"model_tokens", r.model_tokens},
                    {"model_wait_s", r.model_wait_s},
                    {"vision_calls", r.vision_calls},
                    {"fast_path", r.goals_fast_path},
                    {"failure_cause", r.failure_cause},
                    {"start_index", r.start_index},
                    {"losses", r.losses},
                    {"recovery_times_s", r.recovery_times_s},
                    {"recovery_errors_m", r.recovery_errors_m},
                    {"recovery_errors_deg", r.recovery_errors_deg},
                    {"final_pose_error_m", r.final_pose_error_m}});
  }
  out["episodes"] = rows;
  std::ofstream file(path);
  file << out.dump(2) << "\n";
  if (!file) return absl::InternalError(absl::StrCat("cannot write ", path));
  return absl::OkStatus();
}

std::string MissionTable(const std::vector<EpisodeRecord>& records, double success_radius,
                         const NotRun& not_run) {
  std::string table = absl::StrFormat("Success radius %.2f m\n", success_radius);
  for (const char* group : kGroups) {
    const std::vector<EpisodeRecord> in_group = InGroup(records, group);
    const std::vector<StrategySummary> summaries = SummariseByStrategy(in_group);
    if (summaries.empty()) continue;
    absl::StrAppend(
        &table, "\n### ", group, "\n\n",
        "| strategy | episodes | SR | SPL | DTG (m) | path (m) | path / exploration-only | "
        "same, both found (episodes) | time (s) | energy (J) | model calls | fast-path share |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const StrategySummary& s : summaries) {
      const std::optional<double> ratio = PathVsExplorationOnly(summaries, s);
      const std::optional<PairedRatio> paired =
          PathVsExplorationOnlyBothFound(in_group, s.strategy);
      absl::StrAppend(
          &table,
          absl::StrFormat(
              "| %s | %d | %.3f | %.3f | %.2f | %.2f | %s | %s | %.1f | %.0f | %.2f | %.2f |\n",
              s.strategy, s.episodes, s.sr, s.spl, s.dtg_m, s.path_m,
              ratio.has_value() ? absl::StrFormat("%.2f", *ratio) : "-",
              paired.has_value() ? absl::StrFormat("%.2f (%d)", paired->ratio, paired->episodes)
                                 : "-",
              s.time_s, s.energy_j, s.model_calls, s.fast_path_share));
    }
    absl::StrAppend(&table, FailureTable(summaries));
    if (PoseLossGroup(group)) {
      absl::StrAppend(&table,
                      PoseLossTable(SummarisePoseLoss(in_group, InGroup(records, "indoor"))));
    }
  }
  for (const auto& [strategy, reason] : not_run)
    absl::StrAppend(&table, "\n", strategy, " not run: ", reason, "\n");
  return table;
}

}  // namespace semnav::sim::bench
