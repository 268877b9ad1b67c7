#include "clients/sim/bench/mission_report.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

namespace semnav::sim::bench {
namespace {

std::vector<EpisodeRecord> Episodes() {
  EpisodeRecord hit{
      "NEAREST_FRONTIER", "home_1", "chair", true, 2.0, 4.0, 0.5, 20.0, 1600.0, 1, 1, 1,
      "indoor",           ""};
  EpisodeRecord miss{
      "NEAREST_FRONTIER", "home_2", "tv", false, 3.0, 6.0, 2.5, 40.0, 2400.0, 3, 1, 0,
      "indoor",           ""};
  EpisodeRecord uav_base{"NEAREST_FRONTIER",
                         "outdoor_road_vehicles",
                         "car",
                         true,
                         10.0,
                         40.0,
                         0.8,
                         50.0,
                         0.0,
                         0,
                         1,
                         1,
                         "outdoor",
                         ""};
  EpisodeRecord uav{"SEMANTIC_FRONTIER",
                    "outdoor_road_vehicles",
                    "car",
                    true,
                    10.0,
                    20.0,
                    0.6,
                    30.0,
                    0.0,
                    0,
                    1,
                    1,
                    "outdoor",
                    ""};
  // The baseline gave up after 80 m here: only the first outdoor pair counts as "both found".
  EpisodeRecord uav_base_miss{"NEAREST_FRONTIER",
                              "outdoor_river_bridge",
                              "boat",
                              false,
                              10.0,
                              80.0,
                              9.0,
                              250.0,
                              0.0,
                              0,
                              0,
                              0,
                              "outdoor",
                              ""};
  EpisodeRecord uav_hit{"SEMANTIC_FRONTIER",
                        "outdoor_river_bridge",
                        "boat",
                        true,
                        10.0,
                        10.0,
                        0.4,
                        20.0,
                        0.0,
                        0,
                        1,
                        1,
                        "outdoor",
                        ""};
  miss.failure_cause = "budget_spent_exploring";
  hit.model_tokens = 1000;  // the simulated VLM's figures: the miss had none
  hit.model_wait_s = 2.5;
  hit.vision_calls = 3;
  uav_base_miss.failure_cause = "collision_loop";
  return {hit, miss, uav_base, uav_base_miss, uav, uav_hit};
}

TEST(SimBenchMissionReportTest, JsonHoldsTheSeedFormulasPerStrategyAndGroup) {
  const std::string path = ::testing::TempDir() + "/mission_report_test.json";
  ASSERT_TRUE(
      WriteMissionJson(Episodes(), 1.0, {{"EROI_UTILITY", "no model configured"}}, path).ok());
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(path));
  // The headline is the indoor group, with exactly the keys.
  const nlohmann::json& s = json["strategies"]["NEAREST_FRONTIER"];
  EXPECT_EQ(s.size(), 12u);
  EXPECT_EQ(s["episodes"], 2);
  EXPECT_DOUBLE_EQ(s["sr"], 0.5);
  EXPECT_DOUBLE_EQ(s["spl"], 0.25);  // (2 / max(4, 2) + 0) / 2
  EXPECT_DOUBLE_EQ(s["dtg"], 1.5);
  EXPECT_DOUBLE_EQ(s["path_m"], 5.0);
  EXPECT_DOUBLE_EQ(s["time_s"], 30.0);
  EXPECT_DOUBLE_EQ(s["model_calls"], 2.0);
  EXPECT_DOUBLE_EQ(s["fast_path_share"], 0.5);
  EXPECT_DOUBLE_EQ(s["model_tokens"], 500.0);  // (1000 + 0) / 2
  EXPECT_DOUBLE_EQ(s["model_wait_s"], 1.25);
  EXPECT_DOUBLE_EQ(s["vision_calls"], 1.5);
  EXPECT_EQ(s["failures"], nlohmann::json({{"budget_spent_exploring", 1}}));
  EXPECT_FALSE(json["strategies"].contains("SEMANTIC_FRONTIER"));  // outdoor only
  EXPECT_DOUBLE_EQ(json["groups"]["indoor"]["energy_j"]["NEAREST_FRONTIER"], 2000.0);
  const nlohmann::json& outdoor = json["groups"]["outdoor"];
  EXPECT_DOUBLE_EQ(outdoor["strategies"]["SEMANTIC_FRONTIER"]["spl"],
                   0.75);  // (10 / 20 + 10 / 10) / 2
  EXPECT_DOUBLE_EQ(outdoor["path_vs_exploration_only"]["SEMANTIC_FRONTIER"], 0.25);  // 15 m / 60 m
  EXPECT_DOUBLE_EQ(outdoor["path_vs_exploration_only"]["NEAREST_FRONTIER"], 1.0);
  EXPECT_DOUBLE_EQ(outdoor["path_vs_exploration_only_both_found"]["SEMANTIC_FRONTIER"]["ratio"],
                   0.5);  // 20 / 40
  EXPECT_EQ(outdoor["path_vs_exploration_only_both_found"]["SEMANTIC_FRONTIER"]["episodes"], 1);
  EXPECT_EQ(json["not_run"]["EROI_UTILITY"], "no model configured");
  EXPECT_DOUBLE_EQ(json["success_radius_m"], 1.0);
  EXPECT_EQ(json["episodes"].size(), 6u);
  EXPECT_EQ(json["episodes"][2]["group"], "outdoor");
  // Failures by cause per strategy and group; a strategy without failures has an empty map.
  EXPECT_EQ(outdoor["strategies"]["NEAREST_FRONTIER"]["failures"],
            nlohmann::json({{"collision_loop", 1}}));
  EXPECT_TRUE(outdoor["strategies"]["SEMANTIC_FRONTIER"]["failures"].empty());
  EXPECT_EQ(json["episodes"][1]["failure_cause"], "budget_spent_exploring");
  EXPECT_EQ(json["episodes"][0]["failure_cause"], "");
  EXPECT_EQ(json["episodes"][0]["model_tokens"], 1000);
  EXPECT_DOUBLE_EQ(json["episodes"][0]["model_wait_s"], 2.5);
  EXPECT_EQ(json["episodes"][0]["vision_calls"], 3);
  EXPECT_EQ(json["episodes"][1]["model_tokens"], 0);
}

TEST(SimBenchMissionReportTest, TableStatesTheRadiusAndOneRowPerStrategyAndGroup) {
  const std::string table =
      MissionTable(Episodes(), 1.0, {{"EROI_UTILITY", "no model configured"}});
  EXPECT_NE(table.find("Success radius 1.00 m"), std::string::npos);
  EXPECT_NE(table.find("### indoor"), std::string::npos);
  EXPECT_NE(table.find("| NEAREST_FRONTIER | 2 | 0.500 | 0.250 | 1.50 | 5.00 | 1.00 | 1.00 (1) |"),
            std::string::npos);
  EXPECT_NE(table.find("### outdoor"), std::string::npos);
  EXPECT_NE(
      table.find("| SEMANTIC_FRONTIER | 2 | 1.000 | 0.750 | 0.50 | 15.00 | 0.25 | 0.50 (1) |"),
      std::string::npos);
  EXPECT_NE(table.find("EROI_UTILITY not run: no model configured"), std::string::npos);
  // Each group's failures by cause: the indoor miss, the outdoor baseline's collision loop.
  EXPECT_NE(table.find("| strategy | failed | budget_spent_exploring |\n|---|---|---|\n| "
                       "NEAREST_FRONTIER | 1 | 1 |"),
            std::string::npos)
      << table;
  EXPECT_NE(
      table.find(
          "| strategy | failed | collision_loop |\n|---|---|---|\n| NEAREST_FRONTIER | 1 | 1 |\n"
          "| SEMANTIC_FRONTIER | 0 | 0 |"),
      std::string::npos)
      << table;
}

TEST(SimBenchMissionReportTest, PoseLossGroupsReportRecoveriesAndTheSameEpisodesWithoutDrift) {
  EpisodeRecord indoor{"SEMANTIC_FRONTIER",
                       "home_1",
                       "chair",
                       true,
                       2.0,
                       4.0,
                       0.5,
                       20.0,
                       0.0,
                       0,
                       1,
                       1,
                       "indoor",
                       ""};
  indoor.start_index = 0;
  EpisodeRecord indoor_other = indoor;  // another start: not the twin
  indoor_other.start_index = 1;
  indoor_other.success = false;
  EpisodeRecord kidnapped = indoor;
  kidnapped.group = "kidnapped";
  kidnapped.success = false;
  kidnapped.losses = 2;
  kidnapped.recovery_times_s = {9.0, 20.0};  // the second is too slow
  kidnapped.recovery_errors_m = {0.1, 0.1};
  kidnapped.recovery_errors_deg = {1.0, 1.0};
  kidnapped.final_pose_error_m = 0.3;
  EpisodeRecord kidnapped2 = kidnapped;
  kidnapped2.start_index = 1;
  kidnapped2.success = true;
  kidnapped2.losses = 1;
  kidnapped2.recovery_times_s = {5.0};
  kidnapped2.recovery_errors_m = {0.5};  // too far off
  kidnapped2.recovery_errors_deg = {1.0};
  kidnapped2.final_pose_error_m = 0.1;
  const std::vector<PoseLossSummary> summaries =
      SummarisePoseLoss({kidnapped, kidnapped2}, {indoor, indoor_other});
  ASSERT_EQ(summaries.size(), 1u);
  const PoseLossSummary& s = summaries[0];
  EXPECT_EQ(s.episodes, 2);
  EXPECT_EQ(s.losses, 3);
  EXPECT_EQ(s.recoveries, 3);
  EXPECT_EQ(s.recovered_on_target, 1);
  EXPECT_DOUBLE_EQ(s.median_recovery_time_s, 9.0);
  EXPECT_NEAR(s.mean_recovery_error_m, 0.7 / 3, 1e-12);
  EXPECT_DOUBLE_EQ(s.mean_final_pose_error_m, 0.2);
  EXPECT_EQ(s.paired, 2);
  EXPECT_DOUBLE_EQ(s.sr, 0.5);
  EXPECT_DOUBLE_EQ(s.sr_without_drift, 0.5);  // the twins: start 0 succeeded, start 1 did not
  EXPECT_DOUBLE_EQ(s.spl_without_drift, 0.25);

  const std::string path = ::testing::TempDir() + "/mission_report_pose_loss.json";
  ASSERT_TRUE(WriteMissionJson({indoor, indoor_other, kidnapped, kidnapped2}, 1.0, {}, path).ok());
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(path));
  const nlohmann::json& l = json["groups"]["kidnapped"]["localization"]["SEMANTIC_FRONTIER"];
  EXPECT_EQ(l["recovered_on_target"], 1);
  EXPECT_NEAR(l["recovered_on_target_share"].get<double>(), 1.0 / 3, 1e-12);
  EXPECT_EQ(json["episodes"][2]["losses"], 2);
  EXPECT_EQ(json["episodes"][2]["recovery_times_s"].size(), 2u);
  // The indoor headline is unchanged by the pose-loss records.
  EXPECT_EQ(json["strategies"]["SEMANTIC_FRONTIER"]["episodes"], 2);
  EXPECT_NE(MissionTable({indoor, kidnapped}, 1.0).find("same episodes without drift"),
            std::string::npos);
}

TEST(MissionReportTest, OnlyNearestFrontierIsTheExplorationOnlyBaseline) {
  EXPECT_TRUE(IsExplorationOnly("NEAREST_FRONTIER"));
  EXPECT_FALSE(IsExplorationOnly("SEMANTIC_FRONTIER"));
  EXPECT_FALSE(IsExplorationOnly("EROI_UTILITY@0.7"));
  EXPECT_FALSE(IsExplorationOnly("smoke"));
}

}  // namespace
}  // namespace semnav::sim::bench
