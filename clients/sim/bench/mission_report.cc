#include "clients/sim/bench/mission_report.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace semnav::sim::bench {

absl::Status WriteMissionJson(const std::vector<EpisodeRecord>& records, double success_radius,
                              const std::string& path) {
  nlohmann::json out;
  out["success_radius_m"] = success_radius;
  nlohmann::json strategies = nlohmann::json::object();
  for (const StrategySummary& s : SummariseByStrategy(records)) {
    strategies[s.strategy] = {{"sr", s.sr},           {"spl", s.spl},
                              {"dtg", s.dtg_m},       {"path_m", s.path_m},
                              {"time_s", s.time_s},   {"energy_j", s.energy_j},
                              {"model_calls", s.model_calls}, {"fast_path_share", s.fast_path_share},
                              {"episodes", s.episodes}};
  }
  out["strategies"] = strategies;
  nlohmann::json rows = nlohmann::json::array();
  for (const EpisodeRecord& r : records) {
    rows.push_back({{"strategy", r.strategy}, {"world", r.world}, {"target", r.target}, {"success", r.success},
                    {"shortest_path_m", r.shortest_path_m}, {"path_m", r.path_m},
                    {"dtg_m", r.distance_to_goal_m}, {"time_s", r.time_s}, {"energy_j", r.energy_j},
                    {"model_calls", r.model_calls}, {"fast_path", r.goals_fast_path}});
  }
  out["episodes"] = rows;
  std::ofstream file(path);
  file << out.dump(2) << "\n";
  if (!file) return absl::InternalError(absl::StrCat("cannot write ", path));
  return absl::OkStatus();
}

std::string MissionTable(const std::vector<EpisodeRecord>& records, double success_radius) {
  std::string table = absl::StrFormat("Success radius %.2f m\n\n", success_radius);
  absl::StrAppend(&table,
                  "| strategy | episodes | SR | SPL | DTG (m) | path (m) | time (s) | energy (J) | model calls | "
                  "fast-path share |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (const StrategySummary& s : SummariseByStrategy(records)) {
    absl::StrAppend(&table, absl::StrFormat("| %s | %d | %.3f | %.3f | %.2f | %.2f | %.1f | %.0f | %.2f | %.2f |\n",
                                            s.strategy, s.episodes, s.sr, s.spl, s.dtg_m, s.path_m, s.time_s,
                                            s.energy_j, s.model_calls, s.fast_path_share));
  }
  return table;
}

}  // namespace semnav::sim::bench
