// Mission benchmark outputs: JSON per strategy, a Markdown table, a console table.
#pragma once

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "clients/sim/core/episode_metrics.h"

namespace semnav::sim::bench {

// {"success_radius_m": r, "strategies": {NAME: {sr, spl, dtg, path_m, time_s, energy_j,
// model_calls, fast_path_share, episodes}}, "episodes": [per-episode rows]}.
absl::Status WriteMissionJson(const std::vector<EpisodeRecord>& records, double success_radius,
                              const std::string& path);
// The per-strategy table (Markdown, also printed to the console).
std::string MissionTable(const std::vector<EpisodeRecord>& records, double success_radius);

}  // namespace semnav::sim::bench
