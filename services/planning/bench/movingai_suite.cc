#include "services/planning/bench/movingai_suite.h"

#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

#include "services/planning/bench/timing.h"
#include "services/planning/core/astar.h"
#include "services/planning/core/jps.h"
#include "services/planning/core/movingai.h"

namespace semnav::planning::bench {
namespace {

struct MapFile {
  const char* name;
  const char* path;
};

constexpr MapFile kMaps[] = {
    {"arena2", "dao/arena2.map"},
    {"8room_000", "room/8room_000.map"},
    {"maze512-1-0", "maze/maze512-1-0.map"},
    {"random512-10-0", "random/random512-10-0.map"},
    {"Berlin_0_512", "street/Berlin_0_512.map"},
};

struct PlannerStats {
  std::vector<double> ms;
  double expansions = 0;
  int mismatches = 0;
};

template <typename Planner>
void RunRow(Planner& planner, const PassabilityGrid& map, const MovingAiScenario& row,
            PlannerStats* stats) {
  absl::StatusOr<GridPath> path;
  stats->ms.push_back(TimeMs([&] { path = planner.Plan(map, row.start, row.goal); }));
  if (!path.ok() || std::abs(path->length_cells - row.optimal_length) > 1e-4) {
    ++stats->mismatches;
    return;
  }
  stats->expansions += path->expansions;
}

void Merge(const PlannerStats& from, PlannerStats* into) {
  into->ms.insert(into->ms.end(), from.ms.begin(), from.ms.end());
  into->expansions += from.expansions;
  into->mismatches += from.mismatches;
}

}  // namespace

nlohmann::json RunMovingAiSuite(const std::string& data_dir, int threads) {
  nlohmann::json out;
  int total_rows = 0;
  int total_mismatches = 0;
  std::printf("Moving AI rows: A* vs JPS (8-connected, octile, no corner cutting)\n");
  std::printf("%-16s %6s %5s %10s %10s %10s %10s %11s %11s %8s\n", "map", "rows", "bad",
              "astar_med", "astar_p99", "jps_med", "jps_p99", "astar_exp", "jps_exp", "speedup");
  for (const MapFile& file : kMaps) {
    const std::string base = data_dir + "/" + file.path;
    absl::StatusOr<PassabilityGrid> map = LoadMovingAiMap(base);
    absl::StatusOr<std::vector<MovingAiScenario>> rows = LoadMovingAiScenarios(base + ".scen");
    if (!map.ok() || !rows.ok()) {
      std::fprintf(stderr, "cannot load %s: %s %s\n", base.c_str(), map.status().ToString().c_str(),
                   rows.status().ToString().c_str());
      out["error"] = "missing Moving AI data";
      return out;
    }
    // Rows are dealt round-robin to `threads` workers, each with its own
    // planners; every query is still timed on its own.
    std::vector<PlannerStats> a_parts(threads);
    std::vector<PlannerStats> j_parts(threads);
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t) {
      workers.emplace_back([&, t] {
        AStarPlanner astar;
        JpsPlanner jps;
        for (size_t i = t; i < rows->size(); i += threads) {
          RunRow(astar, *map, (*rows)[i], &a_parts[t]);
          RunRow(jps, *map, (*rows)[i], &j_parts[t]);
        }
      });
    }
    for (std::thread& w : workers) w.join();
    PlannerStats a;
    PlannerStats j;
    for (int t = 0; t < threads; ++t) {
      Merge(a_parts[t], &a);
      Merge(j_parts[t], &j);
    }
    const int n = static_cast<int>(rows->size());
    const double a_med = Quantile(a.ms, 0.5);
    const double j_med = Quantile(j.ms, 0.5);
    const double speedup = j_med > 0 ? a_med / j_med : 0.0;
    std::printf("%-16s %6d %5d %10.4f %10.4f %10.4f %10.4f %11.0f %11.0f %8.2f\n", file.name, n,
                a.mismatches + j.mismatches, a_med, Quantile(a.ms, 0.99), j_med,
                Quantile(j.ms, 0.99), a.expansions / n, j.expansions / n, speedup);
    const nlohmann::json per_map = {{"rows", n},
                                    {"astar_mismatches", a.mismatches},
                                    {"jps_mismatches", j.mismatches},
                                    {"astar_ms_median", a_med},
                                    {"astar_ms_p99", Quantile(a.ms, 0.99)},
                                    {"jps_ms_median", j_med},
                                    {"jps_ms_p99", Quantile(j.ms, 0.99)},
                                    {"astar_expansions_mean", a.expansions / n},
                                    {"jps_expansions_mean", j.expansions / n},
                                    {"jps_speedup", speedup}};
    out["maps"][file.name] = per_map;
    for (const char* key : {"jps_ms_median", "astar_ms_median", "jps_speedup"}) {
      out[std::string(file.name) + "." + key] = per_map[key];
    }
    total_rows += n;
    total_mismatches += a.mismatches + j.mismatches;
  }
  out["movingai_rows"] = total_rows;
  out["movingai_mismatches"] = total_mismatches;
  return out;
}

}  // namespace semnav::planning::bench
