// semnav-sim-demo: starts mapping, planning and the gateway beside this program, runs one search
// episode end to end (a generated home the robot has never seen, a target out of sight from the
// start, SEMANTIC_FRONTIER exploration), prints its progress and writes its report and plot.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "clients/sim/bench/mission_plot.h"
#include "clients/sim/bench/mission_report.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/loop/episode_runner.h"
#include "clients/sim/loop/remote_endpoints.h"
#include "clients/sim/loop/search_episode.h"
#include "clients/sim/loop/shortest_path.h"
#include "clients/sim/loop/sim_stack.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "services/common/cli/executable_dir.h"
#include "services/common/cli/flags.h"

namespace {

namespace loop = semnav::sim::loop;
namespace sim = semnav::sim;

const std::vector<semnav::FlagSpec> kFlags = {
    {"out", "DIR", "report folder (default semnav_demo_report)"},
    {"default-ports", "", "start the services on deploy/local.yaml's ports instead of free ones"},
    {"remote", "FILE",
     "start nothing: use FILE's gateway, mapping and planning (docs/operations.md)"},
    {"world-seed", "N", "seed of the generated home (default 11, demo_home_11)"},
    {"help", "", "this text"},
};

void PrintUsage(std::ostream& out) {
  out << "usage: semnav-sim-demo [--out DIR] [--default-ports | --remote FILE] [--world-seed N]\n"
      << semnav::FlagsHelp(kFlags)
      << "Runs one search episode: a generated home, a target out of sight from the start.\n"
         "Exit 0 when the robot finds it, 3 when it does not, 1 when the episode cannot run,\n"
         "2 on bad flags.\n";
}

// Simulated seconds between progress lines; phase changes and the first sight of the target
// are printed when they happen.
constexpr double kProgressEveryS = 5.0;

double Travelled(const std::vector<Eigen::Vector2d>& trajectory) {
  double metres = 0.0;
  for (size_t i = 1; i < trajectory.size(); ++i)
    metres += (trajectory[i] - trajectory[i - 1]).norm();
  return metres;
}

// Appends the labels of newly detected objects to `labels`, so they read in the order seen.
void AddSeenLabels(const sim::World& world, const std::set<int>& seen,
                   std::vector<std::string>& labels) {
  for (const int i : seen) {
    const std::string& label = world.objects[static_cast<size_t>(i)].label;
    if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
  }
}

bool SeesTarget(const sim::World& world, const std::set<int>& seen, const std::string& label) {
  for (const int i : seen) {
    if (world.objects[static_cast<size_t>(i)].label == label) return true;
  }
  return false;
}

// The cells of `like` (the world's grid) that the robot's map observed: mapping's EXPLORED layer
// (map frame = world frame, the odometry starts at the true start pose), sampled at cell centres.
absl::StatusOr<sim::GroundTruthGrid> ExploredCells(const std::shared_ptr<grpc::Channel>& mapping,
                                                   const sim::GroundTruthGrid& like) {
  auto stub = semnav::mapping::v1::MappingService::NewStub(mapping);
  semnav::mapping::v1::GetGridMapRequest request;
  request.add_layers(semnav::common::v1::GRID_LAYER_KIND_EXPLORED);
  semnav::mapping::v1::GetGridMapResponse response;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
  if (const grpc::Status status = stub->GetGridMap(&context, request, &response); !status.ok()) {
    return absl::UnavailableError("GetGridMap: " + status.error_message());
  }
  const semnav::common::v1::GridMap& map = response.grid();
  const std::string* explored = nullptr;
  for (const auto& layer : map.layers()) {
    if (layer.kind() == semnav::common::v1::GRID_LAYER_KIND_EXPLORED) explored = &layer.data();
  }
  if (explored == nullptr || map.resolution() <= 0.0 ||
      explored->size() != static_cast<size_t>(map.width()) * map.height()) {
    return absl::FailedPreconditionError("mapping sent no EXPLORED layer");
  }
  sim::GroundTruthGrid cells = like;
  for (int y = 0; y < like.height; ++y) {
    for (int x = 0; x < like.width; ++x) {
      const Eigen::Vector2d p = like.CellCentre(x, y);
      const int column =
          static_cast<int>(std::floor((p.x() - map.origin().x()) / map.resolution()));
      const int row = static_cast<int>(std::floor((p.y() - map.origin().y()) / map.resolution()));
      const bool inside = column >= 0 && row >= 0 && column < static_cast<int>(map.width()) &&
                          row < static_cast<int>(map.height());
      cells.cells[static_cast<size_t>(y) * like.width + x] =
          inside && (*explored)[static_cast<size_t>(row) * map.width() + column] != 0 ? 1 : 0;
    }
  }
  return cells;
}

}  // namespace

int main(int argc, char** argv) {
  absl::StatusOr<semnav::ParsedFlags> flags = semnav::ParseFlags(argc, argv, 1, kFlags);
  const bool short_help =
      flags.ok() && flags->positional.size() == 1 && flags->positional[0] == "-h";
  if (flags.ok() && !flags->positional.empty() && !short_help) {
    flags = absl::InvalidArgumentError("unexpected argument " + flags->positional[0]);
  }
  if (!flags.ok()) {
    std::cerr << "semnav-sim-demo: " << flags.status().message() << "\n";
    PrintUsage(std::cerr);
    return 2;
  }
  if (flags->Has("help") || short_help) {
    PrintUsage(std::cout);
    return 0;
  }
  if (flags->Has("remote") && flags->Has("default-ports")) {
    std::cerr << "semnav-sim-demo: --remote starts nothing, so --default-ports does not apply\n";
    PrintUsage(std::cerr);
    return 2;
  }
  uint64_t world_seed = loop::kDemoWorldSeed;
  if (auto v = flags->Get("world-seed"); v && !absl::SimpleAtoi(*v, &world_seed)) {
    std::cerr << "semnav-sim-demo: --world-seed: not a non-negative integer: " << *v << "\n";
    PrintUsage(std::cerr);
    return 2;
  }
  std::string out_dir = flags->Get("out").value_or("semnav_demo_report");
  const std::string remote_file = flags->Get("remote").value_or("");

  absl::StatusOr<loop::EpisodeSpec> spec = loop::SearchEpisode(world_seed);
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
    options.free_ports = !flags->Has("default-ports");
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

  const sim::StartPose& start = spec->world.starts[static_cast<size_t>(spec->start_index)];
  const sim::GroundTruthGrid grid = sim::RasterizeOccupancy(
      spec->world,
      sim::BodyRaster(sim::RobotConfig::ForModality(start.modality), start.position.z()));
  const std::optional<sim::NearestGoal> nearest = loop::NearestSuccessPoint(
      spec->world, grid, start.position.head<2>(), spec->target, spec->success_radius);
  std::cout << absl::StrFormat("world %s, start %d, instruction \"find a %s\" (gateway %s)\n",
                               spec->world.name, spec->start_index, spec->target, gateway_address)
            << absl::StrFormat(
                   "  a generated home the robot has never seen (its map starts empty); no %s\n"
                   "  is in sight from the start at (%.1f, %.1f); the nearest is %.1f m away by\n"
                   "  the shortest path. Strategy %s.\n",
                   spec->target, start.position.x(), start.position.y(),
                   nearest ? nearest->length_m : 0.0, spec->strategy)
            << std::flush;

  const auto wall_start = std::chrono::steady_clock::now();
  std::string last_phase;
  double next_report_s = kProgressEveryS;
  bool target_seen = false;
  std::vector<std::string> seen_labels;
  absl::StatusOr<loop::EpisodeResult> result =
      loop::RunEpisode(*spec, *endpoints, [&](int step, const loop::EpisodeResult& so_far) {
        const double sim_s = (step + 1) * spec->step_s;
        const bool phase_changed = so_far.phase != last_phase;
        const bool sees_target =
            !target_seen && SeesTarget(spec->world, so_far.seen_objects, spec->target);
        if (sees_target) {
          target_seen = true;
          std::cout << absl::StrFormat("  t=%5.1fs  the camera sees a %s\n", sim_s, spec->target);
        }
        AddSeenLabels(spec->world, so_far.seen_objects, seen_labels);
        if (phase_changed || sim_s >= next_report_s) {
          last_phase = so_far.phase;
          next_report_s = sim_s + kProgressEveryS;
          std::cout << absl::StrFormat(
              "  t=%5.1fs  %-14s travelled %5.1f m, seen: %s\n", sim_s,
              so_far.phase.empty() ? "-" : so_far.phase, Travelled(so_far.trajectory),
              seen_labels.empty() ? "nothing yet" : absl::StrJoin(seen_labels, ", "));
        }
        std::cout << std::flush;
      });
  if (!result.ok()) {
    std::cerr << "semnav-sim-demo: episode failed to run: " << result.status() << "\n";
    return 1;
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const sim::EpisodeRecord& r = result->record;
  std::cout << absl::StrFormat(
      "%s after %d steps (%.1f s simulated, %.1f s wall): SR %d, SPL %.3f, path %.2f m, "
      "shortest %.2f m, DTG %.2f m (success radius %.1f m), model calls %d, fast path %s, "
      "energy %.0f J\n",
      r.success ? "SUCCESS" : "FAILURE", result->steps, r.time_s, wall_s, r.success ? 1 : 0,
      sim::SuccessWeightedPathLength(r.success, r.shortest_path_m, r.path_m), r.path_m,
      r.shortest_path_m, r.distance_to_goal_m, spec->success_radius, r.model_calls,
      r.goals_fast_path > 0 ? "yes" : "no", r.energy_j);
  if (!r.success && result->steps >= spec->max_steps) {
    std::cout << absl::StrFormat("  the step budget (%d steps) ran out while %s: %s\n",
                                 spec->max_steps, result->phase, result->final_reason);
  } else if (!r.success) {
    std::cout << absl::StrFormat("  the task ended %s: %s\n", result->phase, result->final_reason);
  }

  std::ofstream report(out_dir + "/demo.md");
  report
      << "# semnav demo episode\n\n"
      << absl::StrFormat(
             "%s, start %d: find a %s, out of sight from the start (shortest path %.2f m), %s.\n\n",
             spec->world.name, spec->start_index, spec->target, r.shortest_path_m, spec->strategy)
      << semnav::sim::bench::MissionTable({r}, spec->success_radius)
      << "\n## Timeline (simulated time: the task's phases, every command and the robot's"
         " answer)\n\n```\n";
  for (const std::string& line : result->timeline) report << line << "\n";
  report << "```\n";
  // The plot shows walls and furniture as they are, not grown by the robot's radius.
  sim::RasterOptions true_shapes;
  true_shapes.robot_radius = 0.0;
  const sim::GroundTruthGrid plot_grid = sim::RasterizeOccupancy(spec->world, true_shapes);
  absl::StatusOr<sim::GroundTruthGrid> explored = ExploredCells(endpoints->mapping, plot_grid);
  const absl::Status plotted = explored.ok() ? semnav::sim::bench::WriteExplorationPlot(
                                                   spec->world, plot_grid, *explored, spec->target,
                                                   *result, out_dir + "/demo.png")
                                             : explored.status();
  if (!plotted.ok()) std::cerr << "semnav-sim-demo: no plot: " << plotted << "\n";
  std::cout << "report: " << out_dir << "/demo.md and " << out_dir << "/demo.png\n";
  return r.success ? 0 : 3;
}
