// Closed loop with a model that answers (issue 15): one seed-000 EROI_UTILITY episode, the UAV
// searching the road-with-vehicles scene for a car, with the gateway's vision and region-score
// calls going through the real model proxy to the simulated VLM endpoint. It must find the car.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "clients/sim/loop/episode_runner.h"
#include "clients/sim/loop/sim_stack.h"
#include "clients/sim/vlm/sim_vlm_server.h"
#include "clients/sim/worlds/indoor_generator.h"
#include "clients/sim/worlds/outdoor_scenes.h"

namespace semnav::sim::vlm {
namespace {

// The simulated VLM behind the real model proxy, configured as any OpenAI-compatible vendor, and
// the stack whose gateway asks it; configs go to a fresh folder `name` under the test's temp dir.
struct ModelStack {
  std::unique_ptr<SimVlmServer> endpoint;
  std::unique_ptr<loop::SimStack> stack;
};

absl::StatusOr<ModelStack> StartModelStack(absl::StatusOr<std::unique_ptr<SimVlm>> model,
                                           const std::string& name) {
  if (!model.ok()) return model.status();
  ModelStack started;
  absl::StatusOr<std::unique_ptr<SimVlmServer>> endpoint = SimVlmServer::Start(*std::move(model));
  if (!endpoint.ok()) return endpoint.status();
  started.endpoint = *std::move(endpoint);
  const std::string dir = ::testing::TempDir() + "/" + name;
  std::filesystem::create_directories(dir);
  const std::string proxy_config = dir + "/modelproxy.yaml";
  std::ofstream(proxy_config)
      << "modelproxy:\n  backends:\n    sim:\n      kind: openai\n      base_url: \""
      << started.endpoint->base_url()
      << "\"\n      model: sim-vlm\n      retry: {max_attempts: 1}\n"
         "  aliases:\n    default: [sim, offline]\n";
  absl::StatusOr<std::unique_ptr<loop::SimStack>> stack =
      loop::SimStack::Start({SEMNAV_BIN_DIR, dir, true, proxy_config});
  if (!stack.ok()) return stack.status();
  started.stack = *std::move(stack);
  return started;
}

// What a failed episode is read from: its timeline and every answer the VLM gave.
std::string Transcript(const loop::EpisodeResult& result, const SimVlmServer& endpoint) {
  std::string text;
  for (const std::string& line : result.timeline) absl::StrAppend(&text, line, "\n");
  absl::StrAppend(&text, "VLM answers:\n");
  for (const std::string& answer : endpoint.answers()) absl::StrAppend(&text, answer, "\n");
  return text;
}

// It used to fail: planning's roadmap could not reach any viewpoint from the middle of explored
// space and the gateway's blind fallback steps took the UAV east out of the world (planning's
// EroiUtility regression tests, docs/performance/mission.md).
TEST(SimVlmEpisodeTest, EroiUtilityFindsTheCarThroughTheProxyAndTheSimulatedVlm) {
  loop::EpisodeSpec spec;
  spec.world = RoadVehiclesScene(1);
  spec.start_index = -1;
  for (size_t i = 0; i < spec.world.starts.size(); ++i) {
    if (spec.world.starts[i].modality == Modality::kUav) {
      spec.start_index = static_cast<int>(i);
      break;
    }
  }
  ASSERT_GE(spec.start_index, 0);
  spec.target = "car";
  spec.strategy = "EROI_UTILITY";
  spec.robot_id = "sim-uav-vlm";
  spec.camera_frames = true;
  spec.max_steps = 400;
  spec.seed = 3;

  FrameLog frames;
  spec.on_camera_frame = [&frames](const SensorFrame& frame) { frames.Record(frame); };
  absl::StatusOr<ModelStack> started =
      StartModelStack(SimVlm::Create(spec.world, &frames, SimVlmConfig()), "sim_vlm_episode");
  ASSERT_TRUE(started.ok()) << started.status();
  const SimVlmServer& endpoint = *started->endpoint;

  absl::StatusOr<loop::EpisodeResult> result = loop::RunEpisode(spec, started->stack->endpoints());
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(result->record.success) << result->final_reason << "\n"
                                      << Transcript(*result, endpoint);
  EXPECT_GT(endpoint.requests(), 0);
  EXPECT_LE(result->record.model_calls, 61) << "the per-task budget (60) plus the text embedding";
  std::cout << "steps " << result->steps << ", path " << result->record.path_m << " m, model calls "
            << result->record.model_calls << ", endpoint requests " << endpoint.requests() << "\n";
}

// Open vocabulary closed (issue 15): "找复印机" names a thing the lexicon does not know, so the
// gateway's rules find no step. The model's decompose (the proxy's offline backend, after the
// endpoint declines it) reads FIND(复印机); the slow path shows the model one object per class seen
// and the simulated VLM, which knows a copier is a printer, names the printer; the robot goes
// there. The old gateway refused the instruction before asking any model.
TEST(SimVlmEpisodeTest, CopierTheRulesCannotReadIsDecomposedResolvedAndFound) {
  loop::EpisodeSpec spec;
  IndoorOptions office;
  office.building = Building::kOffice;
  for (uint64_t seed = 1; seed < 40 && spec.world.objects.empty(); ++seed) {
    World world = GenerateIndoor("office", office, seed);
    const int printers = static_cast<int>(
        std::count_if(world.objects.begin(), world.objects.end(),
                      [](const ObjectInstance& object) { return object.label == "printer"; }));
    if (printers == 1) spec.world = std::move(world);
  }
  ASSERT_FALSE(spec.world.objects.empty()) << "no generated office with one printer";
  // The generator's printer stands on a 1.2 m cabinet: with the default 0.35 rad downward pitch a
  // ground robot's camera loses it within 1 m and VERIFY never confirms it (measured: ruled out
  // twice, "not confirmed within reach"). A level camera keeps it in view up close.
  spec.ground_camera_pitch = 0.0;
  spec.target = "复印机";
  spec.target_label = "printer";
  spec.strategy = "SEMANTIC_FRONTIER";
  spec.robot_id = "sim-copier";
  spec.max_steps = 500;
  spec.seed = 2;

  FrameLog frames;
  SimVlmConfig config;
  // An error-free model: this test is about the path (decompose, class grounding, resolution),
  // not the model's mistakes. At default quality its 3 % label confusion per answer, over the ~8
  // match_target calls an open-vocabulary search makes before the printer is in view, sent this
  // episode once to a desk that VERIFY then confirmed (docs/performance/mission.md).
  config.errors = ErrorsAtAccuracy(1.0);
  config.embedding_dim = spec.sensors.detector.embedding_dim;
  config.embedding_seed = spec.sensors.detector.embedding_seed;
  absl::StatusOr<ModelStack> started =
      StartModelStack(SimVlm::Create(spec.world, &frames, config), "sim_vlm_copier");
  ASSERT_TRUE(started.ok()) << started.status();
  const SimVlmServer& endpoint = *started->endpoint;

  absl::StatusOr<loop::EpisodeResult> result = loop::RunEpisode(spec, started->stack->endpoints());
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->trace.instruction_refused) << result->final_reason;
  EXPECT_TRUE(result->record.success) << result->final_reason << "\n"
                                      << Transcript(*result, endpoint);
  std::cout << "world " << spec.world.name << ", steps " << result->steps << ", path "
            << result->record.path_m << " m, model calls " << result->record.model_calls
            << ", endpoint requests " << endpoint.requests() << "\n";
}

}  // namespace
}  // namespace semnav::sim::vlm
