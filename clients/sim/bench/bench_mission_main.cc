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
#include <optional>
#include <string>
#include <thread>

#include "absl/strings/numbers.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_split.h"
#include "absl/synchronization/mutex.h"
#include "clients/sim/bench/episode_plan.h"
#include "clients/sim/bench/mission_plot.h"
#include "clients/sim/bench/mission_report.h"
#include "clients/sim/bench/vlm_sweep_plot.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/world_yaml.h"
#include "clients/sim/loop/episode_runner.h"
#include "clients/sim/loop/sim_stack.h"
#include "clients/sim/vlm/sim_vlm_server.h"
#include "clients/sim/worlds/indoor_generator.h"
#include "semnav/reasoning/v1/operator.pb.h"
#include "services/common/cli/executable_dir.h"
#include "services/common/cli/flags.h"

namespace {

namespace loop = semnav::sim::loop;
namespace sim = semnav::sim;

bool IsEroiUtility(const std::string& strategy) {
  return loop::RequestedStrategy(strategy) ==
         semnav::reasoning::v1::EXPLORATION_STRATEGY_EROI_UTILITY;
}

constexpr char kUsage[] =
    "usage: semnav-bench-mission [--suite DIR] [--episodes N] [--outdoor-episodes N] "
    "[--flyroll-episodes N]\n"
    "                            [--json FILE] [--out DIR] [--seed N] [--max-steps N] "
    "[--strategies LIST]\n"
    "                            [--model-config FILE | --model sim [--vlm-sweep LIST]] [--bin-dir "
    "DIR]\n"
    "                            [--jobs N] [--drift-episodes N] [--kidnapped-episodes N]\n"
    "                            [--landmarks oracle|mapping] [--localizer map|truth]\n"
    "  --suite DIR            folder of world YAML files, or of suite folders (semnav-sim-worlds "
    "--out DIR\n"
    "                         writes indoor, outdoor, flyroll, houseexpo, fr079); default: 4 "
    "generated homes\n"
    "  --episodes N           indoor (ground robot) episodes per strategy (default 4)\n"
    "  --outdoor-episodes N   outdoor (UAV) episodes per strategy (default 0; 15 = 3 scenes x 5 "
    "starts)\n"
    "  --flyroll-episodes N   fly-roll episodes per strategy (default 0)\n"
    "  --json FILE            write the per-strategy figures as JSON\n"
    "  --out DIR              report folder: mission.md, one PNG and one timeline log per episode\n"
    "                         (default mission_report)\n"
    "  --seed N               episode and world seed (default 1)\n"
    "  --max-steps N          step budget per episode, 0.5 s each (default 500, seed 004)\n"
    "  --strategies L         comma list of exploration strategies (default NEAREST_FRONTIER,\n"
    "                         COVERAGE_MAX,SEMANTIC_FRONTIER; EROI_UTILITY needs --model-config)\n"
    "  --model-config FILE    semnav-model-proxy config: run a model proxy in the stack\n"
    "  --model sim            run the simulated VLM (clients/sim/vlm) per stack and a model proxy\n"
    "                         pointed at it; adds EROI_UTILITY and prints model calls, tokens and\n"
    "                         simulated model time per episode\n"
    "  --vlm-sweep LIST       with --model sim: run EROI_UTILITY once per VLM recognition accuracy "
    "of\n"
    "                         the comma list (e.g. 0.5,0.7,0.9; clients/sim/vlm ErrorsAtAccuracy), "
    "each\n"
    "                         labelled EROI_UTILITY@ACC beside the other strategies (run once), "
    "and\n"
    "                         write vlm_sweep.png (outdoor SR and path ratio against accuracy) to "
    "--out\n"
    "  --bin-dir DIR          folder with the service binaries (default: this program's folder)\n"
    "  --drift-episodes N     the first N indoor episodes again with odometry drift, the localizer "
    "model and\n"
    "                         the gateway's relocalization loop: group \"drift\" (default 0)\n"
    "  --kidnapped-episodes N the same with a kidnap 60 s in: group \"kidnapped\" (default 0)\n"
    "  --landmarks L          the pose-loss groups' landmark maps: oracle (the world's objects, "
    "upserted\n"
    "                         before each episode; default) or mapping (filled by mapping)\n"
    "  --localizer R          what the pose-loss groups' localizer model compares the believed "
    "pose with:\n"
    "                         map (the map the robot drew; default) or truth (docs/simulation.md)\n"
    "  --jobs N               episodes run at once, each on its own stack of services (default 2, "
    "one\n"
    "                         per core of the reference machine; 1 = one after another)\n";

// Every flag of kUsage takes a value.
const std::vector<semnav::FlagSpec> kFlags = {{"suite", "DIR", ""},
                                              {"episodes", "N", ""},
                                              {"outdoor-episodes", "N", ""},
                                              {"flyroll-episodes", "N", ""},
                                              {"json", "FILE", ""},
                                              {"out", "DIR", ""},
                                              {"seed", "N", ""},
                                              {"max-steps", "N", ""},
                                              {"strategies", "LIST", ""},
                                              {"model-config", "FILE", ""},
                                              {"model", "NAME", ""},
                                              {"vlm-sweep", "LIST", ""},
                                              {"bin-dir", "DIR", ""},
                                              {"jobs", "N", ""},
                                              {"drift-episodes", "N", ""},
                                              {"kidnapped-episodes", "N", ""},
                                              {"landmarks", "KIND", ""},
                                              {"localizer", "REFERENCE", ""}};

// Compared side by side on the same episodes. EROI_UTILITY needs a vision model, so it joins
// only on request.
constexpr char kDefaultStrategies[] = "NEAREST_FRONTIER,COVERAGE_MAX,SEMANTIC_FRONTIER";

// The worlds of --suite: its YAML files, and those of each sub-folder (sorted by name).
absl::StatusOr<std::vector<sim::World>> Worlds(const std::map<std::string, std::string>& flags,
                                               uint64_t seed) {
  std::vector<sim::World> worlds;
  if (!flags.contains("--suite")) {
    for (uint64_t i = 0; i < 4; ++i) {
      worlds.push_back(sim::GenerateIndoor(absl::StrFormat("home_%d", seed + i),
                                           sim::IndoorOptions{}, seed + i));
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
  if (worlds.empty())
    return absl::NotFoundError(absl::StrCat("--suite ", root.string(), ": no world files"));
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
                                              {"--strategies", kDefaultStrategies},
                                              {"--jobs", "2"},
                                              {"--drift-episodes", "0"},
                                              {"--kidnapped-episodes", "0"},
                                              {"--landmarks", "oracle"},
                                              {"--localizer", "map"}};
  const semnav::ParsedFlags given =
      semnav::ParseFlagsOrExit(argc, argv, kFlags, "semnav-bench-mission", kUsage);
  for (const auto& [name, value] : given.values) flags["--" + name] = value;
  const uint64_t seed = std::strtoull(flags["--seed"].c_str(), nullptr, 10);
  absl::StatusOr<std::vector<sim::World>> worlds = Worlds(flags, seed);
  if (!worlds.ok()) {
    std::cerr << "semnav-bench-mission: " << worlds.status() << "\n";
    return 1;
  }
  const semnav::sim::bench::EpisodeCounts counts{
      std::atoi(flags["--episodes"].c_str()), std::atoi(flags["--outdoor-episodes"].c_str()),
      std::atoi(flags["--flyroll-episodes"].c_str()), std::atoi(flags["--drift-episodes"].c_str()),
      std::atoi(flags["--kidnapped-episodes"].c_str())};
  if (flags["--landmarks"] != "oracle" && flags["--landmarks"] != "mapping") {
    std::cerr << "semnav-bench-mission: --landmarks: oracle or mapping\n" << kUsage;
    return 2;
  }
  if (flags["--localizer"] != "map" && flags["--localizer"] != "truth") {
    std::cerr << "semnav-bench-mission: --localizer: map or truth\n" << kUsage;
    return 2;
  }
  const bool pose_loss = counts.drift > 0 || counts.kidnapped > 0;
  std::vector<std::string> unscorable;
  std::vector<loop::EpisodeSpec> plan =
      semnav::sim::bench::PlanEpisodes(*worlds, counts, seed, &unscorable);
  for (loop::EpisodeSpec& spec : plan) {
    if (!spec.landmarks.empty()) spec.landmarks = flags["--landmarks"];
    spec.localizer.reference = flags["--localizer"] == "truth" ? loop::LocalizerReference::kTruth
                                                               : loop::LocalizerReference::kMap;
  }
  for (const std::string& line : unscorable) std::cerr << "semnav-bench-mission: " << line << "\n";
  if (plan.empty()) {
    std::cerr << "semnav-bench-mission: no episode: no world with objects and a start of a "
                 "requested modality\n";
    return 1;
  }
  const std::string out_dir = flags["--out"];
  std::filesystem::create_directories(out_dir);
  const std::string bin_dir =
      flags.contains("--bin-dir") ? flags["--bin-dir"] : semnav::ExecutableDir();
  semnav::sim::bench::NotRun not_run;
  std::vector<std::string> strategies;
  const std::vector<std::string> requested =
      absl::StrSplit(flags["--strategies"], ',', absl::SkipEmpty());
  for (const std::string& strategy : requested) {
    const semnav::reasoning::v1::ExplorationStrategy parsed = loop::RequestedStrategy(strategy);
    if (parsed == semnav::reasoning::v1::EXPLORATION_STRATEGY_UNSPECIFIED) {
      std::cerr << "semnav-bench-mission: --strategies: unknown strategy " << strategy << "\n"
                << kUsage;
      return 2;
    }
    if (parsed == semnav::reasoning::v1::EXPLORATION_STRATEGY_EROI_UTILITY &&
        !flags.contains("--model-config") && !flags.contains("--model")) {
      not_run[strategy] =
          "no model configured (--model-config): EROI_UTILITY's semantic values come from the "
          "vision model (seed 000)";
      continue;
    }
    strategies.push_back(strategy);
  }
  // Every (strategy, episode) pair is one job; `--jobs` stacks take jobs from one queue. Each
  // task asks for its own strategy, so any stack runs any job, and the records keep plan order.
  // --vlm-sweep: EROI_UTILITY once per recognition accuracy (the other strategies do not read
  // the VLM's clues, so they run once).
  std::vector<double> accuracies;
  for (absl::string_view item : absl::StrSplit(
           flags.contains("--vlm-sweep") ? flags["--vlm-sweep"] : "", ',', absl::SkipEmpty())) {
    double accuracy = -1.0;
    if (!absl::SimpleAtod(item, &accuracy) || !(accuracy >= 0.0 && accuracy <= 1.0)) {
      std::cerr << "semnav-bench-mission: --vlm-sweep: " << item
                << " is not an accuracy in [0, 1]\n"
                << kUsage;
      return 2;
    }
    accuracies.push_back(accuracy);
  }
  if (!accuracies.empty() && (flags["--model"] != "sim" ||
                              std::none_of(strategies.begin(), strategies.end(), IsEroiUtility))) {
    std::cerr
        << "semnav-bench-mission: --vlm-sweep needs --model sim and EROI_UTILITY in --strategies\n"
        << kUsage;
    return 2;
  }
  struct Job {
    std::string strategy;
    size_t episode;
    std::optional<double> accuracy;  // the sweep's VLM accuracy; unset = the default error model
  };
  std::vector<Job> jobs;
  for (const std::string& strategy : strategies) {
    const bool swept = IsEroiUtility(strategy) && !accuracies.empty();
    for (const std::optional<double> accuracy :
         swept ? std::vector<std::optional<double>>(accuracies.begin(), accuracies.end())
               : std::vector<std::optional<double>>{std::nullopt}) {
      for (size_t i = 0; i < plan.size(); ++i) jobs.push_back({strategy, i, accuracy});
    }
  }
  const int workers =
      std::clamp(std::atoi(flags["--jobs"].c_str()), 1, std::max<int>(1, jobs.size()));
  const int max_steps = std::atoi(flags["--max-steps"].c_str());
  std::vector<std::unique_ptr<loop::SimStack>> stacks;
  // --model sim: one simulated VLM endpoint per stack, re-aimed at each episode's world.
  const bool sim_model = flags.contains("--model") && flags.at("--model") == "sim" && !plan.empty();
  if (flags.contains("--model") && !sim_model) {
    std::cerr << "semnav-bench-mission: --model: only 'sim' is known\n" << kUsage;
    return 2;
  }
  std::vector<std::unique_ptr<sim::vlm::SimVlmServer>> endpoints;
  std::vector<std::vector<std::unique_ptr<sim::vlm::FrameLog>>> frame_logs(workers);
  for (int w = 0; w < workers; ++w) {
    loop::SimStackOptions options;
    options.bin_dir = bin_dir;
    options.work_dir = absl::StrCat(out_dir, "/stack_", w);
    if (flags.contains("--model-config")) options.model_proxy_config = flags["--model-config"];
    options.task_time_budget_s = max_steps * loop::EpisodeSpec{}.step_s;
    options.relocalization = pose_loss;
    options.mapping_landmarks = flags["--landmarks"] == "mapping";
    if (sim_model) {
      frame_logs[w].push_back(std::make_unique<sim::vlm::FrameLog>());
      auto model = sim::vlm::SimVlm::Create(plan.front().world, frame_logs[w].back().get(),
                                            sim::vlm::SimVlmConfig());
      auto endpoint =
          model.ok() ? sim::vlm::SimVlmServer::Start(*std::move(model)) : model.status();
      if (!endpoint.ok()) {
        std::cerr << "semnav-bench-mission: simulated VLM: " << endpoint.status() << "\n";
        return 1;
      }
      std::filesystem::create_directories(options.work_dir);
      options.model_proxy_config = absl::StrCat(options.work_dir, "/modelproxy_sim.yaml");
      std::ofstream(options.model_proxy_config)
          << "modelproxy:\n  backends:\n    sim-vlm:\n      kind: openai\n      base_url: \""
          << (*endpoint)->base_url()
          << "\"\n      model: sim-vlm\n      retry: {max_attempts: 1}\n  aliases:\n    default: "
             "[sim-vlm, offline]\n"
             // No answer cache: a question an earlier episode on this stack asked would be
             // answered at once, so an episode would depend on which ran before it (--jobs, load).
             "  cache: {capacity: 0}\n";
      endpoints.push_back(*std::move(endpoint));
    }
    absl::StatusOr<std::unique_ptr<loop::SimStack>> stack = loop::SimStack::Start(options);
    if (!stack.ok()) {
      std::cerr << "semnav-bench-mission: cannot start stack " << w << ": " << stack.status()
                << "\n";
      return 1;
    }
    stacks.push_back(*std::move(stack));
  }
  std::cout << absl::StrFormat(
      "%d episodes x %d strategies on %d stacks (each task asks planning's "
      "SelectExplorationGoal for its strategy)\n",
      plan.size(), strategies.size(), workers);
  // The plots draw each world's true occupancy: rasterised once per world, not per episode
  // (FR-079 has 24,671 boxes); read-only once the workers start.
  std::map<std::string, sim::GroundTruthGrid> plot_grids;
  for (const loop::EpisodeSpec& spec : plan) {
    if (!plot_grids.contains(spec.world.name)) {
      plot_grids.emplace(spec.world.name,
                         sim::RasterizeOccupancy(spec.world, sim::RasterOptions{}));
    }
  }
  const auto started = std::chrono::steady_clock::now();
  std::vector<std::optional<sim::EpisodeRecord>> slots(jobs.size());
  absl::Mutex mutex;
  size_t next_job = 0, done = 0;
  absl::Status failure;
  auto work = [&](loop::SimStack& stack, int worker) {
    for (;;) {
      size_t j;
      {
        absl::MutexLock lock(&mutex);
        if (next_job == jobs.size() || !failure.ok()) return;
        j = next_job++;
      }
      loop::EpisodeSpec spec = plan[jobs[j].episode];
      spec.strategy = jobs[j].strategy;
      // One robot id per episode: the gateway keeps a robot's topological memory across
      // sessions, and which episodes ran before on this stack depends on --jobs.
      spec.robot_id = absl::StrCat(spec.robot_id, "-", spec.strategy, "-", jobs[j].episode);
      // The VLM's input (seed 000).
      spec.camera_frames = loop::RequestedStrategy(spec.strategy) ==
                           semnav::reasoning::v1::EXPLORATION_STRATEGY_EROI_UTILITY;
      spec.max_steps = max_steps;
      sim::vlm::SimVlmServer::Served model_before;
      if (sim_model) {  // this episode's world and frames (the worker's episodes run one at a time)
        sim::vlm::FrameLog* frames =
            frame_logs[worker].emplace_back(std::make_unique<sim::vlm::FrameLog>()).get();
        sim::vlm::SimVlmConfig config;
        if (jobs[j].accuracy) config.errors = sim::vlm::ErrorsAtAccuracy(*jobs[j].accuracy);
        // Its text encoder speaks the episode's detector's embedding space.
        config.embedding_dim = spec.sensors.detector.embedding_dim;
        config.embedding_seed = spec.sensors.detector.embedding_seed;
        auto model = sim::vlm::SimVlm::Create(spec.world, frames, config);
        if (model.ok()) endpoints[worker]->Replace(*std::move(model));
        spec.on_camera_frame = [frames](const sim::SensorFrame& frame) { frames->Record(frame); };
        model_before = endpoints[worker]->served();
      }
      const auto episode_started = std::chrono::steady_clock::now();
      absl::StatusOr<loop::EpisodeResult> result = loop::RunEpisode(spec, stack.endpoints());
      if (!result.ok()) {
        absl::MutexLock lock(&mutex);
        failure = result.status();
        return;
      }
      const std::string label =
          jobs[j].accuracy ? semnav::sim::bench::SweepLabel(spec.strategy, *jobs[j].accuracy)
                           : spec.strategy;
      result->record.strategy = label;
      const std::string stem = absl::StrFormat("%s/%s_episode_%02d_%s", out_dir, label,
                                               jobs[j].episode, spec.world.name);
      std::ofstream log(stem + ".log");
      for (const std::string& line : result->timeline) log << line << "\n";
      std::string model_line;
      if (sim_model) {
        const sim::vlm::SimVlmServer::Served after = endpoints[worker]->served();
        const double model_s =
            static_cast<double>(after.latency_ms - model_before.latency_ms) / 1000.0;
        model_line =
            absl::StrFormat(" model: %d calls (gateway), %d answers, %d tokens, %.1f s model time",
                            result->record.model_calls, after.answers - model_before.answers,
                            after.tokens - model_before.tokens, model_s);
        log << "model:" << model_line << "\n";
        result->record.model_tokens = after.tokens - model_before.tokens;
        result->record.model_wait_s = model_s;
        result->record.vision_calls = after.vision_answers - model_before.vision_answers;
      }
      if (absl::Status s =
              semnav::sim::bench::WriteEpisodePlot(spec.world, plot_grids.at(spec.world.name),
                                                   spec.target_label, *result, stem + ".png");
          !s.ok()) {
        std::cerr << "semnav-bench-mission: " << s << "\n";
      }
      absl::MutexLock lock(&mutex);
      slots[j] = result->record;
      ++done;
      const auto now = std::chrono::steady_clock::now();
      const double wall_s = std::chrono::duration<double>(now - episode_started).count();
      const double eta_s = std::chrono::duration<double>(now - started).count() / done *
                           static_cast<double>(jobs.size() - done);
      std::cout << absl::StrFormat(
                       "[%d/%d] %s %s %s start %d: find %s: %s in %d steps, DTG %.2f m, path %.1f "
                       "m, l %.1f m (%s) "
                       "[%.0f s wall, %.0f s left]%s\n",
                       done, jobs.size(), label, result->record.group, spec.world.name,
                       spec.start_index, spec.target, result->record.success ? "SUCCESS" : "fail",
                       result->steps, result->record.distance_to_goal_m, result->record.path_m,
                       result->record.shortest_path_m, result->final_reason, wall_s, eta_s,
                       model_line)
                << std::flush;
    }
  };
  {
    std::vector<std::thread> threads;
    for (size_t w = 0; w < stacks.size(); ++w)
      threads.emplace_back(work, std::ref(*stacks[w]), static_cast<int>(w));
    for (std::thread& t : threads) t.join();
  }
  if (!failure.ok()) {
    std::cerr << "semnav-bench-mission: episode failed to run: " << failure << "\n";
    return 1;
  }
  std::vector<sim::EpisodeRecord> records;
  for (const std::optional<sim::EpisodeRecord>& r : slots) records.push_back(*r);
  std::cout << absl::StrFormat(
      "%d episodes in %.0f s wall\n", records.size(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  const std::string table =
      semnav::sim::bench::MissionTable(records, sim::kDefaultSuccessRadius, not_run);
  std::cout << "\n" << table;
  std::ofstream(out_dir + "/mission.md") << "# Mission benchmark\n\n" << table;
  if (flags.contains("--json")) {
    if (absl::Status s = semnav::sim::bench::WriteMissionJson(records, sim::kDefaultSuccessRadius,
                                                              not_run, flags["--json"]);
        !s.ok()) {
      std::cerr << "semnav-bench-mission: " << s << "\n";
      return 1;
    }
  }
  if (!accuracies.empty()) {
    const std::vector<semnav::sim::bench::SweepPoint> points =
        semnav::sim::bench::SweepSummary(records, "outdoor", "EROI_UTILITY", accuracies);
    std::cout
        << "\nVLM-quality sweep, outdoor EROI_UTILITY:\n\n| accuracy | episodes | SR | path / "
        << "NEAREST_FRONTIER (both found) | vision calls | model calls |\n"
        << "|---|---|---|---|---|---|\n";
    for (const semnav::sim::bench::SweepPoint& p : points) {
      std::cout << absl::StrFormat(
          "| %.2f | %d | %.3f | %s | %.1f | %.1f |\n", p.accuracy, p.episodes, p.sr,
          p.path_ratio ? absl::StrFormat("%.2f (%d)", *p.path_ratio, p.paired_episodes) : "-",
          p.vision_calls, p.model_calls);
    }
    if (absl::Status s = semnav::sim::bench::WriteVlmSweepPlot(
            points,
            absl::StrFormat("outdoor EROI_UTILITY, %d episodes per accuracy (simulated VLM)",
                            points.front().episodes),
            out_dir + "/vlm_sweep.png");
        !s.ok()) {
      std::cerr << "semnav-bench-mission: " << s << "\n";
      return 1;
    }
  }
  std::cout << "report: " << out_dir << "/mission.md (PNG plots and timelines beside it)\n";
  return 0;
}
