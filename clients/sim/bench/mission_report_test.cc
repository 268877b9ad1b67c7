#include "clients/sim/bench/mission_report.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

namespace semnav::sim::bench {
namespace {

std::vector<EpisodeRecord> TwoEpisodes() {
  EpisodeRecord hit{"NEAREST_FRONTIER", "home_1", "chair", true, 2.0, 4.0, 0.5, 20.0, 1600.0, 1, 1, 1};
  EpisodeRecord miss{"NEAREST_FRONTIER", "home_2", "tv", false, 3.0, 6.0, 2.5, 40.0, 2400.0, 3, 1, 0};
  return {hit, miss};
}

TEST(SimBenchMissionReportTest, JsonHoldsTheSeedFormulasPerStrategy) {
  const std::string path = ::testing::TempDir() + "/mission_report_test.json";
  ASSERT_TRUE(WriteMissionJson(TwoEpisodes(), 1.0, path).ok());
  const nlohmann::json json = nlohmann::json::parse(std::ifstream(path));
  const nlohmann::json& s = json["strategies"]["NEAREST_FRONTIER"];
  EXPECT_EQ(s["episodes"], 2);
  EXPECT_DOUBLE_EQ(s["sr"], 0.5);
  EXPECT_DOUBLE_EQ(s["spl"], 0.25);  // (2 / max(4, 2) + 0) / 2
  EXPECT_DOUBLE_EQ(s["dtg"], 1.5);
  EXPECT_DOUBLE_EQ(s["path_m"], 5.0);
  EXPECT_DOUBLE_EQ(s["time_s"], 30.0);
  EXPECT_DOUBLE_EQ(s["model_calls"], 2.0);
  EXPECT_DOUBLE_EQ(s["fast_path_share"], 0.5);
  EXPECT_DOUBLE_EQ(json["success_radius_m"], 1.0);
  EXPECT_EQ(json["episodes"].size(), 2u);
}

TEST(SimBenchMissionReportTest, TableStatesTheRadiusAndOneRowPerStrategy) {
  const std::string table = MissionTable(TwoEpisodes(), 1.0);
  EXPECT_NE(table.find("Success radius 1.00 m"), std::string::npos);
  EXPECT_NE(table.find("| NEAREST_FRONTIER | 2 | 0.500 | 0.250 | 1.50 |"), std::string::npos);
}

}  // namespace
}  // namespace semnav::sim::bench
