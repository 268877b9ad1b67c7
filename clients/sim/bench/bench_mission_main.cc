// semnav-bench-mission: closed-loop search episodes through the real services, scored with
// seed 004's SR / SPL / DTG; writes JSON, a Markdown table and one top-down PNG per episode.
#include <unistd.h>

#include <algorithm>
#include <chrono>
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
#include "services/common/cli/executable_dir.h"

namespace {

namespace loop = semnav::sim::loop;
namespace sim = semnav::sim;

constexpr char kUsage[] =
    "usage: semnav-bench-mission [--suite DIR] [--episodes N] [--outdoor-episodes N] [--flyroll-episodes N]\n"
    "                            [--json FILE] [--out DIR] [--seed N] [--max-steps N] [--strategies LIST]\n"
    "                            [--model-config FILE] [--bin-dir DIR]\n"
    "  --suite DIR            folder of world YAML files, or of suite folders (semnav-sim-worlds --out DIR\n"
    "                         writes indoor, outdoor, flyroll, houseexpo, fr079); default: 4 generated homes\n"
    "  --episodes N           indoor (ground robot) episodes per strategy (default 4)\n"
    "  --outdoor-episodes N   outdoor (UAV) episodes per strategy (default 0; 15 = 3 scenes x 5 starts)\n"
    "  --flyroll-episodes N   fly-roll episodes per strategy (default 0)\n"
    "  --json FILE            write the per-strategy figures as JSON\n"
    "  --out DIR              report folder: mission.md, one PNG and one timeline log per episode\n"
    "                         (default mission_report)\n"
    "  --seed N               episode and world seed (default 1)\n"
    "  --max-steps N          step budget per episode, 0.5 s each (default 500, seed 004)\n"
    "  --strategies L         comma list of exploration strategies (default NEAREST_FRONTIER,\n"
    "                         COVERAGE_MAX,SEMANTIC_FRONTIER; EROI_UTILITY needs --model-config)\n"
    "  --model-config FILE    semnav-model-proxy config: run a model proxy in the stack\n"
    "  --bin-dir DIR          folder with the service binaries (default: this program's folder)\n";

// Compared side by side on the same episodes, each with its own stack whose gateway explores
// by that strategy. EROI_UTILITY needs a vision model, so it joins only on request.
constexpr char kDefaultStrategies[] = "NEAREST_FRONTIER,COVERAGE_MAX,SEMANTIC_FRONTIER";

// The worlds of --suite: its YAML files, and those of each sub-folder (sorted by name).
absl::StatusOr<std::vector<sim::World>> Worlds(const std::map<std::string, std::string>& flags, uint64_t seed) {
  std::vector<sim::World> worlds;
  if (!flags.contains("--suite")) {
    for (uint64_t i = 0; i < 4; ++i) {
      worlds.push_back(sim::GenerateIndoor(absl::StrFormat("home_%d", seed + i), sim::IndoorOptions{}, seed + i));
    }
    return worlds;
  }
  const std::filesystem::path root = flags.at("--suite");
  std::vector<std::filesystem::path> folders{root};
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(root, error)) {
    if (entry.is_directory()) folders.push_back(entry.path());
  }
  std::sort(folders.begin() + 1, folders.end());
  for (const std::filesystem::path& folder : folders) {
    absl::StatusOr<std::vector<sim::World>> suite = sim::LoadSuite(folder.string());
    if (!suite.ok()) return suite.status();
    worlds.insert(worlds.end(), suite->begin(), suite->end());
  }
  if (worlds.empty()) return absl::NotFoundError(absl::StrCat("--suite ", root.string(), ": no world files"));
  return worlds;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> flags = {{"--episodes", "4"},
                                              {"--outdoor-episodes", "0"},
                                              {"--flyroll-episodes", "0"},
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
  const semnav::sim::bench::EpisodeCounts counts{std::atoi(flags["--episodes"].c_str()),
                                                 std::atoi(flags["--outdoor-episodes"].c_str()),
                                                 std::atoi(flags["--flyroll-episodes"].c_str())};
  const std::vector<loop::EpisodeSpec> plan = semnav::sim::bench::PlanEpisodes(*worlds, counts, seed);
  if (plan.empty()) {
    std::cerr << "semnav-bench-mission: no episode: no world with objects and a start of a requested modality\n";
    return 1;
  }
  const std::string out_dir = flags["--out"];
  std::filesystem::create_directories(out_dir);
  const std::string bin_dir = flags.contains("--bin-dir") ? flags["--bin-dir"] : semnav::ExecutableDir();
  std::vector<sim::EpisodeRecord> records;
  semnav::sim::bench::NotRun not_run;
  std::vector<std::string> strategies;
  const std::vector<std::string> requested = absl::StrSplit(flags["--strategies"], ',', absl::SkipEmpty());
  for (const std::string& strategy : requested) {
    if (strategy == "EROI_UTILITY" && !flags.contains("--model-config")) {
      not_run[strategy] = "no model configured (--model-config): EROI_UTILITY's semantic values come from the "
                          "vision model (seed 000)";
      continue;
    }
    strategies.push_back(strategy);
  }
  const auto started = std::chrono::steady_clock::now();
  const size_t total = plan.size() * strategies.size();
  for (const std::string& strategy : strategies) {
    loop::SimStackOptions options;
    options.bin_dir = bin_dir;
    options.work_dir = out_dir + "/stack_" + strategy;
    options.exploration_strategy = strategy;
    if (flags.contains("--model-config")) options.model_proxy_config = flags["--model-config"];
    absl::StatusOr<std::unique_ptr<loop::SimStack>> stack = loop::SimStack::Start(options);
    if (!stack.ok()) {
      std::cerr << "semnav-bench-mission: cannot start the stack for " << strategy << ": " << stack.status() << "\n";
      not_run[strategy] = absl::StrCat("the stack did not start: ", stack.status().message());
      continue;
    }
    std::cout << "strategy " << strategy << " (the gateway explores with planning's "
              << "SelectExplorationGoal)\n";
    for (size_t i = 0; i < plan.size(); ++i) {
      loop::EpisodeSpec spec = plan[i];
      spec.strategy = strategy;
      spec.max_steps = std::atoi(flags["--max-steps"].c_str());
      const std::string group = sim::ReportGroup(spec.world.starts[spec.start_index].modality);
      std::cout << absl::StrFormat("[%d/%d] %s %s start %d: find %s ... ", records.size() + 1, total, group,
                                   spec.world.name, spec.start_index, spec.target)
                << std::flush;
      const auto episode_started = std::chrono::steady_clock::now();
      absl::StatusOr<loop::EpisodeResult> result = loop::RunEpisode(spec, (*stack)->endpoints());
      if (!result.ok()) {
        std::cerr << "\nsemnav-bench-mission: episode failed to run: " << result.status() << "\n";
        return 1;
      }
      records.push_back(result->record);
      const auto now = std::chrono::steady_clock::now();
      const double wall_s = std::chrono::duration<double>(now - episode_started).count();
      const double eta_s = std::chrono::duration<double>(now - started).count() / records.size() *
                           static_cast<double>(total - records.size());
      std::cout << absl::StrFormat("%s in %d steps, DTG %.2f m, path %.1f m, l %.1f m (%s) [%.0f s wall, %.0f s left]\n",
                                   result->record.success ? "SUCCESS" : "fail", result->steps,
                                   result->record.distance_to_goal_m, result->record.path_m,
                                   result->record.shortest_path_m, result->final_reason, wall_s, eta_s);
      const std::string stem = absl::StrFormat("%s/%s_episode_%02d_%s", out_dir, strategy, i, spec.world.name);
      std::ofstream log(stem + ".log");
      for (const std::string& line : result->timeline) log << line << "\n";
      sim::RasterOptions raster;
      const sim::GroundTruthGrid grid = sim::RasterizeOccupancy(spec.world, raster);
      if (absl::Status s = semnav::sim::bench::WriteEpisodePlot(spec.world, grid, spec.target_label, *result,
                                                                stem + ".png");
          !s.ok()) {
        std::cerr << "semnav-bench-mission: " << s << "\n";
      }
    }
  }
  const std::string table = semnav::sim::bench::MissionTable(records, sim::kDefaultSuccessRadius, not_run);
  std::cout << "\n" << table;
  std::ofstream(out_dir + "/mission.md") << "# Mission benchmark\n\n" << table;
  if (flags.contains("--json")) {
    if (absl::Status s = semnav::sim::bench::WriteMissionJson(records, sim::kDefaultSuccessRadius, not_run,
                                                              flags["--json"]);
        !s.ok()) {
      std::cerr << "semnav-bench-mission: " << s << "\n";
      return 1;
    }
  }
  std::cout << "report: " << out_dir << "/mission.md (PNG plots and timelines beside it)\n";
  return 0;
}
