// semnav-bench-sim: simulator sensor timings on the benchmark worlds (Google Benchmark).
// `--json FILE` writes the named figures as a flat JSON object; --benchmark_* flags go to the
// library.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "clients/sim/core/depth_noise.h"
#include "clients/sim/core/detector.h"
#include "clients/sim/core/rgb_image.h"
#include "clients/sim/core/sim_robot.h"
#include "clients/sim/core/view_renderer.h"
#include "clients/sim/core/world_yaml.h"
#include "clients/sim/worlds/benchmark_suite.h"
#include "services/common/cli/benchmark_flags.h"
#include "services/common/cli/help.h"

namespace semnav::sim {
namespace {

struct Case {
  std::string name;
  World world;
};

// The first world of each suite.
std::vector<Case>& Cases() {
  static std::vector<Case> cases = [] {
    std::vector<Case> out;
    const auto suite = BuildBenchmarkSuite(1, SEMNAV_SHARED_DATA_DIR);
    if (!suite.ok()) {
      std::cerr << "semnav-bench-sim: " << suite.status() << "\n";
      return out;
    }
    std::string last;
    for (const SuiteWorld& w : *suite) {
      if (w.suite == last) continue;
      last = w.suite;
      out.push_back({w.suite + "/" + w.world.name, w.world});
    }
    return out;
  }();
  return cases;
}

Eigen::Isometry3d StartCamera(const World& world) {
  const StartPose& start = world.starts.front();
  const RobotConfig robot = RobotConfig::ForModality(start.modality);
  return CameraPoseInWorld(start.position + Eigen::Vector3d(0, 0, robot.camera_height), start.yaw,
                           robot.camera_pitch);
}

void BM_RenderDepth(benchmark::State& state, const Case* c) {
  const Scene scene = Scene::Build(c->world);
  const CameraIntrinsics k;
  const Eigen::Isometry3d pose = StartCamera(c->world);
  for (auto _ : state) {
    RenderedView view = RenderView(scene, k, pose, 0.3, 8.0);
    benchmark::DoNotOptimize(view.depth.data());
  }
}

void BM_FullFrame(benchmark::State& state, const Case* c) {
  const Scene scene = Scene::Build(c->world);
  SensorConfig sensors;
  sensors.rgb = true;
  SimRobot robot(c->world, scene, c->world.starts.front(),
                 RobotConfig::ForModality(c->world.starts.front().modality), sensors, 1);
  for (auto _ : state) {
    SensorFrame frame = robot.Capture();
    benchmark::DoNotOptimize(frame.depth.data());
  }
}

void BM_LoadWorldYaml(benchmark::State& state, const Case* c) {
  const std::string text = WorldToYaml(c->world);
  for (auto _ : state) {
    absl::StatusOr<World> world = ParseWorldYaml(text);
    benchmark::DoNotOptimize(world.ok());
  }
}

void BM_BuildScene(benchmark::State& state, const Case* c) {
  for (auto _ : state) {
    Scene scene = Scene::Build(c->world);
    benchmark::DoNotOptimize(scene.solids().data());
  }
}

// Collects wall and CPU milliseconds per benchmark for the --json file (every benchmark is
// registered with millisecond units, which the adjusted times are expressed in).
class FigureReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      figures[run.benchmark_name() + "_wall_ms"] = run.GetAdjustedRealTime();
      figures[run.benchmark_name() + "_cpu_ms"] = run.GetAdjustedCPUTime();
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> figures;
};

}  // namespace
}  // namespace semnav::sim

int main(int argc, char** argv) {
  constexpr char kUsage[] =
      "usage: semnav-bench-sim [--json FILE] [--benchmark_* flags]\n"
      "Depth render and full sensor frame time per world source.\n";
  using namespace semnav::sim;
  const semnav::ParsedFlags flags = semnav::ParseBenchmarkFlagsOrExit(
      &argc, argv, {{"json", "FILE", ""}}, "semnav-bench-sim", kUsage);
  const std::string json_path = flags.Get("json").value_or("");
  for (const Case& c : Cases()) {
    benchmark::RegisterBenchmark(("render_depth_640x480/" + c.name).c_str(), BM_RenderDepth, &c)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("full_frame_rgb_detections/" + c.name).c_str(), BM_FullFrame, &c)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("build_scene/" + c.name).c_str(), BM_BuildScene, &c)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("parse_world_yaml/" + c.name).c_str(), BM_LoadWorldYaml, &c)
        ->Unit(benchmark::kMillisecond);
  }
  FigureReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!json_path.empty()) {
    std::ofstream out(json_path);
    out << "{";
    const char* sep = "";
    for (const auto& [name, ms] : reporter.figures) {
      out << sep << "\n  \"" << name << "\": " << ms;
      sep = ",";
    }
    out << "\n}\n";
  }
  return 0;
}
