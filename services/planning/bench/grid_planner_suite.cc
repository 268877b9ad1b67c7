#include "services/planning/bench/grid_planner_suite.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "services/planning/bench/timing.h"
#include "services/planning/core/grid_planner.h"
#include "services/planning/core/movingai.h"

namespace semnav::planning::bench {
namespace {

struct MapFile {
  const char* name;
  const char* path;
};

// Rooms and doors, and an open arena: the shapes the robot's live maps have.
constexpr MapFile kMaps[] = {{"8room_000", "room/8room_000.map"}, {"arena2", "dao/arena2.map"}};
constexpr size_t kRows = 300;  // the first rows of each scenario file (short to long)

}  // namespace

nlohmann::json RunGridPlannerSuite(const std::string& data_dir) {
  nlohmann::json out;
  std::printf("GridPlanner (PlanPath 2D) at 0.05 m cells: clearance off (JPS) vs on (A* + cost)\n");
  std::printf("%-12s %5s %10s %10s %10s %10s %12s\n", "map", "rows", "off_med", "off_p99", "on_med",
              "on_p99", "length_ratio");
  for (const MapFile& file : kMaps) {
    const std::string base = data_dir + "/" + file.path;
    absl::StatusOr<PassabilityGrid> map = LoadMovingAiMap(base);
    absl::StatusOr<std::vector<MovingAiScenario>> rows = LoadMovingAiScenarios(base + ".scen");
    if (!map.ok() || !rows.ok()) {
      out["error"] = "missing Moving AI data";
      return out;
    }
    GridPlannerConfig off_config;
    off_config.clearance.clearance_m = 0.0;
    GridPlanner off(off_config);
    GridPlanner on(GridPlannerConfig{});
    std::vector<double> off_ms, on_ms;
    double off_length = 0.0, on_length = 0.0;
    const size_t n = std::min(kRows, rows->size());
    for (size_t i = 0; i < n; ++i) {
      GridPlanRequest request;
      request.free = *map;
      request.resolution_m = 0.05;
      request.start = (*rows)[i].start;
      request.goal = (*rows)[i].goal;
      request.keep_clearance = true;
      absl::StatusOr<GridPlanResult> a, b;
      off_ms.push_back(TimeMs([&] { a = off.Plan(request); }));
      on_ms.push_back(TimeMs([&] { b = on.Plan(request); }));
      if (a.ok() && b.ok()) {
        off_length += a->path.length_cells;
        on_length += b->path.length_cells;
      }
    }
    const double ratio = off_length > 0 ? on_length / off_length : 0.0;
    std::printf("%-12s %5zu %10.3f %10.3f %10.3f %10.3f %12.3f\n", file.name, n,
                Quantile(off_ms, 0.5), Quantile(off_ms, 0.99), Quantile(on_ms, 0.5),
                Quantile(on_ms, 0.99), ratio);
    const std::string key = std::string("grid_planner.") + file.name;
    out[key + ".clearance_off_ms_median"] = Quantile(off_ms, 0.5);
    out[key + ".clearance_off_ms_p99"] = Quantile(off_ms, 0.99);
    out[key + ".clearance_on_ms_median"] = Quantile(on_ms, 0.5);
    out[key + ".clearance_on_ms_p99"] = Quantile(on_ms, 0.99);
    out[key + ".length_ratio"] = ratio;
  }
  return out;
}

}  // namespace semnav::planning::bench
