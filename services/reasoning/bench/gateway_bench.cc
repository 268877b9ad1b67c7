// semnav-bench-gateway: core figures of the gateway (see docs/performance/gateway.md).
//   fast_resolve_us_p99        fast-path resolve over a 502-object graph with 512-d embeddings
//                              (wall clock; fast_resolve_cpu_us_p99: thread CPU time)
//   esca_objects_kept          ESCA selective grounding of a 200-object graph
//   esca_token_reduction       1 - prompt tokens after / before grounding
//   fast_path_ratio            share of the fixed instruction set decided by the fast path
//   instruction_to_first_command_us_p99  in-process decompose + resolve + first robot command
//   instruction_to_command_ms_p99        loopback gRPC with real semnav-mapping and semnav-planning
//                                        (instruction_to_command_planned: samples with a planned
//                                        path)
//   instruction_to_command_with_model_ms_p99  the same with semnav-model-proxy configured (issue
//   15)
// Usage: semnav-bench-gateway [--json FILE] [--benchmark_* flags]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "benchmark/benchmark.h"
#include "nlohmann/json.hpp"
#include "services/common/cli/benchmark_flags.h"
#include "services/common/cli/help.h"
#include "services/reasoning/bench/loopback_latency.h"
#include "services/reasoning/core/fast_resolver.h"
#include "services/reasoning/core/scene_graph_json.h"
#include "services/reasoning/core/selective_grounding.h"
#include "services/reasoning/core/task_decomposer.h"
#include "services/reasoning/core/task_executor.h"
#include "services/reasoning/testing/fixture.h"
#include "services/reasoning/testing/synthetic_scene.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

constexpr int kEmbeddingDims = 512;
constexpr int kSamples = 3000;

TargetSpec ExtinguisherNearDoor() {
  TargetSpec target;
  target.name = "fire extinguisher";
  target.colours = {"red"};
  target.relation = "near";
  target.anchor = "door";
  return target;
}

std::vector<float> TextEmbedding() {
  std::vector<float> text(kEmbeddingDims);
  for (int i = 0; i < kEmbeddingDims; ++i)
    text[static_cast<std::size_t>(i)] = static_cast<float>((i * 7) % 13) - 6.0f;
  return text;
}

double ThreadCpuMicros() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e6 + static_cast<double>(now.tv_nsec) / 1e3;
}

struct P99 {
  double wall_us = 0.0;  // includes preemption by other processes on a loaded machine
  double cpu_us = 0.0;   // this thread's CPU time only
};

template <typename F>
P99 P99Micros(F&& body) {
  std::vector<double> wall, cpu;
  wall.reserve(kSamples);
  cpu.reserve(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const double cpu_start = ThreadCpuMicros();
    const auto start = std::chrono::steady_clock::now();
    body();
    wall.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count());
    cpu.push_back(ThreadCpuMicros() - cpu_start);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  const auto at = static_cast<std::size_t>(0.99 * (kSamples - 1));
  return {wall[at], cpu[at]};
}

// Straight segment to the goal; frontiers never needed because the target is in the scene.
class DirectPlanner : public PathPlanner {
 public:
  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) override {
    return std::vector<Eigen::Vector3d>{query.start, query.goal};
  }
  absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery&) override {
    return absl::NotFoundError("not used");
  }
};

void BM_FastResolve500(benchmark::State& state) {
  const SceneGraph graph = testing::SyntheticScene(25, 20, kEmbeddingDims);
  const FastResolver resolver(&ShippedLexicon(), FastResolverConfig{});
  const std::vector<float> text = TextEmbedding();
  for (auto _ : state)
    benchmark::DoNotOptimize(resolver.Resolve(ExtinguisherNearDoor(), graph, text, {}));
}
BENCHMARK(BM_FastResolve500);

void BM_Esca200(benchmark::State& state) {
  const SceneGraph graph = testing::SyntheticScene(18, 11);
  const LabelMatcher matcher(&ShippedLexicon(), 0.5);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        SelectiveGrounding(ExtinguisherNearDoor(), graph, matcher, GroundingConfig{}));
  }
}
BENCHMARK(BM_Esca200);

nlohmann::json Figures() {
  nlohmann::json figures;
  const FastResolver resolver(&ShippedLexicon(), FastResolverConfig{});
  {
    const SceneGraph graph = testing::SyntheticScene(25, 20, kEmbeddingDims);
    const std::vector<float> text = TextEmbedding();
    figures["fast_resolve_objects"] = graph.objects.size();
    const P99 resolve = P99Micros([&] {
      benchmark::DoNotOptimize(resolver.Resolve(ExtinguisherNearDoor(), graph, text, {}));
    });
    figures["fast_resolve_us_p99"] = resolve.wall_us;
    figures["fast_resolve_cpu_us_p99"] = resolve.cpu_us;
  }
  {
    const SceneGraph graph = testing::SyntheticScene(18, 11);
    const GroundedGraph grounded =
        SelectiveGrounding(ExtinguisherNearDoor(), graph, resolver.matcher(), GroundingConfig{});
    figures["esca_objects_in"] = graph.objects.size();
    figures["esca_objects_kept"] = grounded.graph.objects.size();
    figures["esca_target_kept"] = grounded.graph.FindObject(testing::kSyntheticTargetId) != nullptr;
    figures["esca_token_reduction"] =
        1.0 - static_cast<double>(EstimateTokens(SceneGraphToPromptJson(grounded.graph))) /
                  EstimateTokens(SceneGraphToPromptJson(graph));
  }
  absl::StatusOr<SceneGraph> scene = testing::LoadSceneGraph(testing::FastPathScenePath());
  absl::StatusOr<std::vector<testing::InstructionCase>> cases =
      testing::LoadInstructionSet(testing::FastPathInstructionsPath());
  if (!scene.ok() || !cases.ok()) {
    std::fprintf(stderr, "fixtures: %s %s\n", scene.status().ToString().c_str(),
                 cases.status().ToString().c_str());
    std::exit(1);
  }
  TaskDecomposer decomposer(InstructionParser(&ShippedLexicon(), *TextSegmenter::Create()),
                            DecomposerConfig{});
  int fast = 0;
  for (const testing::InstructionCase& c : *cases) {
    const Decomposition decomposition = decomposer.Decompose(c.instruction);
    const TargetSpec* target = PrimaryTarget(decomposition.subgoals);
    if (target != nullptr && resolver.Resolve(*target, *scene, {}, {}).accepted) ++fast;
  }
  figures["fast_path_instructions"] = cases->size();
  figures["fast_path_ratio"] = static_cast<double>(fast) / static_cast<double>(cases->size());
  DirectPlanner planner;
  figures["instruction_to_first_command_us_p99"] =
      P99Micros([&] {
        Decomposition decomposition = decomposer.Decompose("去红色灭火器旁边");
        TaskExecutor task("去红色灭火器旁边", std::move(decomposition.subgoals), &resolver,
                          &planner, nullptr, {});
        task.OnSceneGraph(0, *scene);
        benchmark::DoNotOptimize(task.Start(0, RobotPose{}));
      }).wall_us;
  for (const bool with_model : {false, true}) {
    absl::StatusOr<LoopbackLatency> loopback = MeasureInstructionToCommand(200, with_model);
    const std::string prefix =
        with_model ? "instruction_to_command_with_model_" : "instruction_to_command_";
    if (loopback.ok()) {
      figures[prefix + "ms_p50"] = loopback->p50_ms;
      figures[prefix + "ms_p99"] = loopback->p99_ms;
      figures[prefix + "samples"] = loopback->samples;
      figures[prefix + "planned"] = loopback->planned;
    } else {
      std::fprintf(stderr, "%s not measured: %s\n", prefix.c_str(),
                   loopback.status().ToString().c_str());
    }
  }
  return figures;
}

}  // namespace
}  // namespace semnav::reasoning

int main(int argc, char** argv) {
  constexpr char kUsage[] =
      "usage: semnav-bench-gateway [--json FILE] [--benchmark_* flags]\n"
      "Fast-path resolve, ESCA grounding and instruction-to-command latency of the gateway.\n";
  const semnav::ParsedFlags flags = semnav::ParseBenchmarkFlagsOrExit(
      &argc, argv, {{"json", "FILE", ""}}, "semnav-bench-gateway", kUsage);
  const std::string json_path = flags.Get("json").value_or("");
  benchmark::RunSpecifiedBenchmarks();
  const nlohmann::json figures = semnav::reasoning::Figures();
  std::printf("\n%-40s %s\n", "figure", "value");
  for (const auto& [name, value] : figures.items())
    std::printf("%-40s %s\n", name.c_str(), value.dump().c_str());
  if (!json_path.empty()) {
    std::ofstream out(json_path);
    out << figures.dump(2) << "\n";
    if (!out) {
      std::fprintf(stderr, "cannot write %s\n", json_path.c_str());
      return 1;
    }
  }
  return 0;
}
