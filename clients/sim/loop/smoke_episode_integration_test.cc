// The closed loop end to end: real mapping, planning and gateway on free ports; the simulated
// robot finds an in-sight object in a generated home through the public contracts only.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "clients/sim/core/world_yaml.h"
#include "clients/sim/loop/episode_runner.h"
#include "clients/sim/loop/search_episode.h"
#include "clients/sim/loop/sim_stack.h"
#include "clients/sim/loop/smoke_episode.h"

namespace semnav::sim::loop {
namespace {

TEST(SimLoopIntegrationTest, SmokeEpisodeFindsTheTargetInSight) {
  absl::StatusOr<EpisodeSpec> spec = SmokeEpisode(7);
  ASSERT_TRUE(spec.ok()) << spec.status();
  absl::StatusOr<std::unique_ptr<SimStack>> stack =
      SimStack::Start({SEMNAV_BIN_DIR, ::testing::TempDir() + "/sim_loop_smoke", true, ""});
  ASSERT_TRUE(stack.ok()) << stack.status();

  absl::StatusOr<EpisodeResult> result = RunEpisode(*spec, (*stack)->endpoints());
  ASSERT_TRUE(result.ok()) << result.status();
  SCOPED_TRACE(absl::StrCat("target ", spec->target, ", task ", result->final_reason, ", steps ",
                            result->steps));
  EXPECT_EQ(result->final_status, semnav::reasoning::v1::TASK_STATUS_SUCCEEDED);
  EXPECT_TRUE(result->stop_issued);
  EXPECT_TRUE(result->record.success);
  EXPECT_LE(result->record.distance_to_goal_m, kDefaultSuccessRadius);
  // The in-sight target is 1.5-3.5 m away: l_i is positive and no longer than the path taken
  // plus the success-radius slack; SPL is then in (0, 1].
  EXPECT_GT(result->record.shortest_path_m, 0.0);
  const double spl =
      SuccessWeightedPathLength(true, result->record.shortest_path_m, result->record.path_m);
  EXPECT_GT(spl, 0.0);
  EXPECT_LE(spl, 1.0);
}

// The demo's episode: the bed is out of sight from the start (search_episode_test.cc), so the
// robot must explore with SEMANTIC_FRONTIER before it can see and reach it. (Until the success
// region became geodesic the demo looked for the couch, whose 1 m disc reached through a wall.)
TEST(SimLoopIntegrationTest, SearchEpisodeFindsTheTargetOutOfSight) {
  absl::StatusOr<EpisodeSpec> spec = SearchEpisode();
  ASSERT_TRUE(spec.ok()) << spec.status();
  absl::StatusOr<std::unique_ptr<SimStack>> stack =
      SimStack::Start({SEMNAV_BIN_DIR, ::testing::TempDir() + "/sim_loop_search", true, ""});
  ASSERT_TRUE(stack.ok()) << stack.status();

  absl::StatusOr<EpisodeResult> result = RunEpisode(*spec, (*stack)->endpoints());
  ASSERT_TRUE(result.ok()) << result.status();
  SCOPED_TRACE(absl::StrCat("task ", result->final_reason, ", steps ", result->steps));
  EXPECT_EQ(result->final_status, semnav::reasoning::v1::TASK_STATUS_SUCCEEDED);
  EXPECT_TRUE(result->record.success);
  // It explored before it saw the bed, and took a longer way than the 4.33 m shortest path.
  EXPECT_NEAR(result->record.shortest_path_m, 4.33, 0.05);
  EXPECT_GT(result->record.path_m, result->record.shortest_path_m);
  EXPECT_TRUE(
      std::any_of(result->timeline.begin(), result->timeline.end(),
                  [](const std::string& line) { return absl::StrContains(line, " exploring: "); }));
  bool saw_target = false;
  for (const int i : result->seen_objects) {
    saw_target = saw_target || spec->world.objects[static_cast<size_t>(i)].label == spec->target;
  }
  EXPECT_TRUE(saw_target);
}

TEST(SimLoopIntegrationTest, ChineseTargetNameFindsTheSameTable) {
  absl::StatusOr<EpisodeSpec> spec = SmokeEpisode(7);
  ASSERT_TRUE(spec.ok()) << spec.status();
  ASSERT_EQ(spec->target, "dining table");  // world seed 7's in-sight object
  spec->target = "餐桌";                    // instruction "找餐桌"
  spec->target_label = "dining table";
  absl::StatusOr<std::unique_ptr<SimStack>> stack =
      SimStack::Start({SEMNAV_BIN_DIR, ::testing::TempDir() + "/sim_loop_smoke_zh", true, ""});
  ASSERT_TRUE(stack.ok()) << stack.status();
  absl::StatusOr<EpisodeResult> result = RunEpisode(*spec, (*stack)->endpoints());
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->final_status, semnav::reasoning::v1::TASK_STATUS_SUCCEEDED)
      << result->final_reason;
  EXPECT_TRUE(result->record.success);
  EXPECT_EQ(result->record.goals_fast_path, 1);

  // A target the gateway cannot parse (no model to ask) is a failed episode, scored from where
  // the robot stands, not a broken run; the stack keeps serving.
  spec->target = "zqxwv";
  absl::StatusOr<EpisodeResult> refused = RunEpisode(*spec, (*stack)->endpoints());
  ASSERT_TRUE(refused.ok()) << refused.status();
  EXPECT_EQ(refused->final_status, semnav::reasoning::v1::TASK_STATUS_FAILED);
  EXPECT_TRUE(absl::StartsWith(refused->final_reason, "instruction refused: INVALID_ARGUMENT"))
      << refused->final_reason;
  EXPECT_FALSE(refused->record.success);
  EXPECT_EQ(refused->steps, 0);
  EXPECT_EQ(refused->record.path_m, 0.0);
  EXPECT_GE(refused->record.distance_to_goal_m,
            1.5);  // taken at the start, >= 1.5 m from any table
}

// Regression (hand-drawn flat "laptop", generated HouseExpo room "cup", 2026-11-28): the point
// 0.5 m short of the object lay in furniture, seed 004's line-of-sight point stopped 1.1-1.2 m
// away, and the robot set the target aside or stopped outside the success region. The approach
// now stands at the free point nearest the object within reach, on whichever side that is.
TEST(SimLoopIntegrationTest, ObjectsWhoseNearSideIsBlockedAreReachedFromAnotherSide) {
  absl::StatusOr<World> world =
      LoadWorldFile(SEMNAV_SOURCE_DIR "/tests/worlds/regression/study_and_kitchen_reach.yaml");
  ASSERT_TRUE(world.ok()) << world.status();
  absl::StatusOr<std::unique_ptr<SimStack>> stack =
      SimStack::Start({SEMNAV_BIN_DIR, ::testing::TempDir() + "/sim_loop_reach", true, ""});
  ASSERT_TRUE(stack.ok()) << stack.status();
  for (const auto& [start, target] : {std::pair<int, std::string>{0, "laptop"}, {1, "cup"}}) {
    EpisodeSpec spec;
    spec.world = *world;
    spec.start_index = start;
    spec.target = target;
    spec.strategy = "SEMANTIC_FRONTIER";
    spec.robot_id = "sim-robot-" + target;
    spec.max_steps = 240;
    absl::StatusOr<EpisodeResult> result = RunEpisode(spec, (*stack)->endpoints());
    ASSERT_TRUE(result.ok()) << result.status();
    std::string timeline;
    for (const std::string& line : result->timeline) timeline += line + "\n";
    SCOPED_TRACE(absl::StrCat(target, ": ", result->final_reason, "\n", timeline));
    EXPECT_EQ(result->final_status, semnav::reasoning::v1::TASK_STATUS_SUCCEEDED);
    EXPECT_TRUE(result->record.success);
    EXPECT_LE(result->record.distance_to_goal_m, kDefaultSuccessRadius);
    // Before: the laptop was set aside twice ("the approach cannot get within the success
    // radius") and the cup once ("could not reach it after 3 re-plans").
    EXPECT_FALSE(absl::StrContains(timeline, "set aside"));
  }
}

// EROI_UTILITY's input (seed 000): with camera frames on the robot session, the gateway asks the
// vision model about them. The stack's model proxy is the offline default, which cannot read
// images, so the calls fail, but each is made and counted; without frames there are none.
TEST(SimLoopIntegrationTest, EroiEpisodeSendsCameraFramesToTheVisionModel) {
  absl::StatusOr<EpisodeSpec> spec = SmokeEpisode(7);
  ASSERT_TRUE(spec.ok()) << spec.status();
  spec->target = "fire extinguisher";  // no home has one: the robot keeps exploring
  spec->strategy = "EROI_UTILITY";
  spec->max_steps = 30;
  const std::string dir = ::testing::TempDir() + "/sim_loop_eroi";
  std::filesystem::create_directories(dir);
  const std::string proxy_config = dir + "/modelproxy.yaml";
  std::ofstream(proxy_config) << "modelproxy: {}\n";
  absl::StatusOr<std::unique_ptr<SimStack>> stack =
      SimStack::Start({SEMNAV_BIN_DIR, dir, true, proxy_config});
  ASSERT_TRUE(stack.ok()) << stack.status();

  absl::StatusOr<EpisodeResult> blind = RunEpisode(*spec, (*stack)->endpoints());
  ASSERT_TRUE(blind.ok()) << blind.status();
  spec->camera_frames = true;
  spec->robot_id = "sim-robot-camera";
  absl::StatusOr<EpisodeResult> seeing = RunEpisode(*spec, (*stack)->endpoints());
  ASSERT_TRUE(seeing.ok()) << seeing.status();
  EXPECT_FALSE(seeing->record.success);
  // Frames reach the vision model, but a failed call backs off (1 s, doubling) and only a new
  // view asks: no longer a call per frame (issue 15's 636-call storm), at most one per back-off.
  EXPECT_GE(seeing->record.model_calls, blind->record.model_calls + 1)
      << "without frames " << blind->record.model_calls << ", with frames "
      << seeing->record.model_calls;
  EXPECT_LE(seeing->record.model_calls, blind->record.model_calls + 8)
      << "without frames " << blind->record.model_calls << ", with frames "
      << seeing->record.model_calls;
}

}  // namespace
}  // namespace semnav::sim::loop
