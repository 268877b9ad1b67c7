// semnav-bench-mission: closed-loop search episodes through the real services, scored with
// seed 004's SR / SPL / DTG; writes JSON, a Markdown table and one top-down PNG per episode.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

#include "absl/strings/str_format.h"
#include "absl/strings/str_split.h"
#include "clients/sim/bench/episode_plan.h"
#include "clients/sim/bench/mission_plot.h"
#include "clients/sim/bench/mission_report.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/world_yaml.h"
#include "clients/sim/loop/episode_runner.h"
#include "clients/sim/loop/sim_stack.h"
#include "clients/sim/worlds/indoor_generator.h"

namespace {

namespace loop = semnav::sim::loop;
namespace sim = semnav::sim;

constexpr char kUsage[] =
    "usage: semnav-bench-mission [--suite DIR] [--episodes N] [--json FILE] [--out DIR] [--seed N]\n"
    "                            [--max-steps N] [--strategies LIST] [--bin-dir DIR]\n"
    "  --suite DIR      folder of world YAML files (default: 4 generated homes)\n"
    "  --episodes N     episodes per strategy (default 4)\n"
    "  --json FILE      write the per-strategy figures as JSON\n"
    "  --out DIR        report folder: mission.md and one PNG per episode (default mission_report)\n"
    "  --seed N         episode and world seed (default 1)\n"
    "  --max-steps N    step budget per episode, 0.5 s each (default 500, seed 004)\n"
    "  --strategies L   comma list of exploration strategies (default NEAREST_FRONTIER,\n"
    "                   COVERAGE_MAX,SEMANTIC_FRONTIER; EROI_UTILITY needs a vision model)\n"
    "  --bin-dir DIR    folder with the service binaries (default: this program's folder)\n";

// Compared side by side on the same episodes, each with its own stack whose gateway explores
// by that strategy. EROI_UTILITY needs a vision model, so it joins only on request.
constexpr char kDefaultStrategies[] = "NEAREST_FRONTIER,COVERAGE_MAX,SEMANTIC_FRONTIER";

std::string ProgramDir() {
  return std::filesystem::canonical("/proc/self/exe").parent_path().string();
}

absl::StatusOr<std::vector<sim::World>> Worlds(const std::map<std::string, std::string>& flags, uint64_t seed) {
  if (flags.contains("--suite")) return sim::LoadSuite(flags.at("--suite"));
  std::vector<sim::World> worlds;
  for (uint64_t i = 0; i < 4; ++i) {
    worlds.push_back(sim::GenerateIndoor(absl::StrFormat("home_%d", seed + i), sim::IndoorOptions{}, seed + i));
  }
  return worlds;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> flags = {{"--episodes", "4"},
                                              {"--out", "mission_report"},
                                              {"--seed", "1"},
                                              {"--max-steps", "500"},
                                              {"--strategies", kDefaultStrategies}};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    }
    if (arg.rfind("--", 0) == 0 && i + 1 < argc) {
      flags[arg] = argv[++i];
    } else {
      std::cerr << "semnav-bench-mission: bad argument " << arg << "\n" << kUsage;
      return 2;
    }
  }
  const uint64_t seed = std::strtoull(flags["--seed"].c_str(), nullptr, 10);
  absl::StatusOr<std::vector<sim::World>> worlds = Worlds(flags, seed);
  if (!worlds.ok()) {
    std::cerr << "semnav-bench-mission: " << worlds.status() << "\n";
    return 1;
  }
  std::vector<loop::EpisodeSpec> plan = semnav::sim::bench::PlanEpisodes(*worlds, std::atoi(flags["--episodes"].c_str()), seed);
  if (plan.empty()) {
    std::cerr << "semnav-bench-mission: no world with a ground start and objects\n";
    return 1;
  }
  const std::string out_dir = flags["--out"];
  std::filesystem::create_directories(out_dir);
  const std::string bin_dir = flags.contains("--bin-dir") ? flags["--bin-dir"] : ProgramDir();
  std::vector<sim::EpisodeRecord> records;
  const std::vector<std::string> strategies =
      absl::StrSplit(flags["--strategies"], ',', absl::SkipEmpty());
  for (const std::string& strategy : strategies) {
    absl::StatusOr<std::unique_ptr<loop::SimStack>> stack =
        loop::SimStack::Start({bin_dir, out_dir + "/stack_" + strategy, true, strategy});
    if (!stack.ok()) {
      std::cerr << "semnav-bench-mission: cannot start the stack: " << stack.status() << "\n";
      return 1;
    }
    std::cout << "strategy " << strategy << " (the gateway explores with planning's "
              << "SelectExplorationGoal)\n";
    for (size_t i = 0; i < plan.size(); ++i) {
      loop::EpisodeSpec spec = plan[i];
      spec.strategy = strategy;
      spec.max_steps = std::atoi(flags["--max-steps"].c_str());
      std::cout << absl::StrFormat("[%d/%d] %s start %d: find %s ... ", i + 1, plan.size(),
                                   spec.world.name, spec.start_index, spec.target)
                << std::flush;
      absl::StatusOr<loop::EpisodeResult> result = loop::RunEpisode(spec, (*stack)->endpoints());
      if (!result.ok()) {
        std::cerr << "\nsemnav-bench-mission: episode failed to run: " << result.status() << "\n";
        return 1;
      }
      records.push_back(result->record);
      std::cout << absl::StrFormat("%s in %d steps, DTG %.2f m, path %.1f m, l %.1f m (%s)\n",
                                   result->record.success ? "SUCCESS" : "fail", result->steps,
                                   result->record.distance_to_goal_m, result->record.path_m,
                                   result->record.shortest_path_m, result->final_reason);
      sim::RasterOptions raster;
      const sim::GroundTruthGrid grid = sim::RasterizeOccupancy(spec.world, raster);
      const std::string stem = absl::StrFormat("%s/%s_episode_%02d_%s", out_dir, strategy, i, spec.world.name);
      std::ofstream log(stem + ".log");
      for (const std::string& line : result->timeline) log << line << "\n";
      const std::string png = stem + ".png";
      if (absl::Status s = semnav::sim::bench::WriteEpisodePlot(spec.world, grid, spec.target,
                                                                *result, png);
          !s.ok()) {
        std::cerr << "semnav-bench-mission: " << s << "\n";
      }
    }
  }
  const std::string table = semnav::sim::bench::MissionTable(records, sim::kDefaultSuccessRadius);
  std::cout << "\n" << table;
  std::ofstream(out_dir + "/mission.md") << "# Mission benchmark\n\n" << table;
  if (flags.contains("--json")) {
    if (absl::Status s = semnav::sim::bench::WriteMissionJson(records, sim::kDefaultSuccessRadius, flags["--json"]);
        !s.ok()) {
      std::cerr << "semnav-bench-mission: " << s << "\n";
      return 1;
    }
  }
  std::cout << "report: " << out_dir << "/mission.md (PNG plots beside it)\n";
  return 0;
}
