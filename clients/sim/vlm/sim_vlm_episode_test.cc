// Closed loop with a model that answers (issue 15): one seed-000 EROI_UTILITY episode, the UAV
// searching the road-with-vehicles scene for a car, with the gateway's vision and region-score
// calls going through the real model proxy to the simulated VLM endpoint. It must find the car.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "clients/sim/loop/episode_runner.h"
#include "clients/sim/loop/sim_stack.h"
#include "clients/sim/vlm/sim_vlm_server.h"
#include "clients/sim/worlds/outdoor_scenes.h"

namespace semnav::sim::vlm {
namespace {

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
  absl::StatusOr<std::unique_ptr<SimVlm>> model =
      SimVlm::Create(spec.world, &frames, SimVlmConfig());
  ASSERT_TRUE(model.ok()) << model.status();
  absl::StatusOr<std::unique_ptr<SimVlmServer>> endpoint = SimVlmServer::Start(*std::move(model));
  ASSERT_TRUE(endpoint.ok()) << endpoint.status();

  const std::string dir = ::testing::TempDir() + "/sim_vlm_episode";
  std::filesystem::create_directories(dir);
  const std::string proxy_config = dir + "/modelproxy.yaml";
  std::ofstream(proxy_config)
      << "modelproxy:\n  backends:\n    sim:\n      kind: openai\n      base_url: \""
      << (*endpoint)->base_url()
      << "\"\n      model: sim-vlm\n      retry: {max_attempts: 1}\n"
         "  aliases:\n    default: [sim, offline]\n";
  absl::StatusOr<std::unique_ptr<loop::SimStack>> stack =
      loop::SimStack::Start({SEMNAV_BIN_DIR, dir, true, proxy_config});
  ASSERT_TRUE(stack.ok()) << stack.status();

  absl::StatusOr<loop::EpisodeResult> result = loop::RunEpisode(spec, (*stack)->endpoints());
  ASSERT_TRUE(result.ok()) << result.status();
  std::string timeline;
  for (const std::string& line : result->timeline) absl::StrAppend(&timeline, line, "\n");
  std::string answers;
  for (const std::string& answer : (*endpoint)->answers()) absl::StrAppend(&answers, answer, "\n");
  EXPECT_TRUE(result->record.success) << result->final_reason << "\n"
                                      << timeline << "VLM answers:\n"
                                      << answers;
  EXPECT_GT((*endpoint)->requests(), 0);
  EXPECT_LE(result->record.model_calls, 61) << "the per-task budget (60) plus the text embedding";
  std::cout << "steps " << result->steps << ", path " << result->record.path_m << " m, model calls "
            << result->record.model_calls << ", endpoint requests " << (*endpoint)->requests()
            << "\n";
}

}  // namespace
}  // namespace semnav::sim::vlm
