// semnav-sim-demo: starts mapping, planning and the gateway beside this program, runs one short
// indoor episode end to end (a generated home, an object in sight) and writes its report.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "absl/strings/str_format.h"
#include "clients/sim/bench/mission_plot.h"
#include "clients/sim/bench/mission_report.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/loop/episode_runner.h"
#include "clients/sim/loop/remote_endpoints.h"
#include "clients/sim/loop/sim_stack.h"
#include "clients/sim/loop/smoke_episode.h"
#include "services/common/cli/executable_dir.h"

namespace {

namespace loop = semnav::sim::loop;
namespace sim = semnav::sim;

constexpr char kUsage[] =
    "usage: semnav-sim-demo [--out DIR] [--default-ports | --remote FILE]\n"
    "  --out DIR         report folder (default semnav_demo_report)\n"
    "  --default-ports   start the services on deploy/local.yaml's ports instead of free ones\n"
    "  --remote FILE     start nothing: use the gateway, mapping and planning of FILE's client\n"
    "                    sections (address, tls.*, auth.*; see docs/operations.md)\n";

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = "semnav_demo_report";
  bool free_ports = true;
  std::string remote_file;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else if (arg == "--remote" && i + 1 < argc) {
      remote_file = argv[++i];
    } else if (arg == "--default-ports") {
      free_ports = false;
    } else {
      std::cerr << (arg == "--help" || arg == "-h" ? "" : "semnav-sim-demo: bad argument " + arg + "\n") << kUsage;
      return arg == "--help" || arg == "-h" ? 0 : 2;
    }
  }
  absl::StatusOr<loop::EpisodeSpec> spec = loop::SmokeEpisode(7);
  if (!spec.ok()) {
    std::cerr << "semnav-sim-demo: " << spec.status() << "\n";
    return 1;
  }
  out_dir = std::filesystem::absolute(out_dir).string();
  std::filesystem::create_directories(out_dir);
  std::unique_ptr<loop::SimStack> stack;
  absl::StatusOr<loop::Endpoints> endpoints;
  std::string gateway_address = "from " + remote_file;
  if (!remote_file.empty()) {
    endpoints = loop::LoadRemoteEndpoints(remote_file);
  } else {
    const std::string bin_dir = semnav::ExecutableDir();
    std::cout << "starting mapping, planning and gateway from " << bin_dir << " ..." << std::endl;
    loop::SimStackOptions options;
    options.bin_dir = bin_dir;
    options.work_dir = out_dir + "/stack";
    options.free_ports = free_ports;
    absl::StatusOr<std::unique_ptr<loop::SimStack>> started = loop::SimStack::Start(options);
    if (started.ok()) {
      stack = *std::move(started);
      endpoints = stack->endpoints();
      gateway_address = stack->gateway_address();
    } else {
      endpoints = started.status();
    }
  }
  if (!endpoints.ok()) {
    std::cerr << "semnav-sim-demo: cannot reach the stack: " << endpoints.status() << "\n";
    return 1;
  }
  std::cout << absl::StrFormat("world %s, start %d, instruction \"find a %s\" (gateway %s)\n", spec->world.name,
                               spec->start_index, spec->target, gateway_address);
  absl::StatusOr<loop::EpisodeResult> result =
      loop::RunEpisode(*spec, *endpoints, [](int step, const loop::EpisodeResult&) {
        if (step % 20 == 19) std::cout << "  step " << step + 1 << "\n" << std::flush;
      });
  if (!result.ok()) {
    std::cerr << "semnav-sim-demo: episode failed to run: " << result.status() << "\n";
    return 1;
  }
  const sim::EpisodeRecord& r = result->record;
  std::cout << absl::StrFormat(
      "%s after %d steps (%.1f s simulated): DTG %.2f m (success radius %.1f m), path %.2f m, shortest %.2f m, "
      "SPL %.3f, energy %.0f J, model calls %d, fast path %s\n",
      r.success ? "SUCCESS" : "FAILURE", result->steps, r.time_s, r.distance_to_goal_m, sim::kDefaultSuccessRadius,
      r.path_m, r.shortest_path_m, sim::SuccessWeightedPathLength(r.success, r.shortest_path_m, r.path_m),
      r.energy_j, r.model_calls, r.goals_fast_path > 0 ? "yes" : "no");
  std::ofstream report(out_dir + "/demo.md");
  report << "# semnav demo episode\n\n" << semnav::sim::bench::MissionTable({r}, sim::kDefaultSuccessRadius)
         << "\n## Timeline (simulated time: the task's phases, every command and the robot's answer)\n\n```\n";
  for (const std::string& line : result->timeline) report << line << "\n";
  report << "```\n";
  const sim::GroundTruthGrid grid = sim::RasterizeOccupancy(spec->world, sim::RasterOptions{});
  if (absl::Status s = semnav::sim::bench::WriteEpisodePlot(spec->world, grid, spec->target, *result,
                                                            out_dir + "/demo.png");
      !s.ok()) {
    std::cerr << "semnav-sim-demo: " << s << "\n";
  }
  std::cout << "report: " << out_dir << "/demo.md and " << out_dir << "/demo.png\n";
  return r.success ? 0 : 3;
}
