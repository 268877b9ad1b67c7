#include "clients/sim/bench/vlm_sweep_plot.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

namespace semnav::sim::bench {
namespace {

EpisodeRecord Outdoor(const std::string& strategy, bool success, double path_m, int vision_calls) {
  EpisodeRecord r;
  r.strategy = strategy;
  r.group = "outdoor";
  r.success = success;
  r.path_m = path_m;
  r.vision_calls = vision_calls;
  return r;
}

// Two episodes: the baseline finds both (40 m, 60 m). At 0.5 the model-guided search finds only
// the first (30 m); at 0.9 both (20 m, 30 m).
std::vector<EpisodeRecord> Sweep() {
  return {Outdoor("NEAREST_FRONTIER", true, 40, 0),
          Outdoor("NEAREST_FRONTIER", true, 60, 0),
          Outdoor(SweepLabel("EROI_UTILITY", 0.5), true, 30, 20),
          Outdoor(SweepLabel("EROI_UTILITY", 0.5), false, 90, 30),
          Outdoor(SweepLabel("EROI_UTILITY", 0.9), true, 20, 10),
          Outdoor(SweepLabel("EROI_UTILITY", 0.9), true, 30, 12)};
}

TEST(SimBenchVlmSweepTest, SummaryPairsEachAccuracyWithTheBaseline) {
  EXPECT_EQ(SweepLabel("EROI_UTILITY", 0.7), "EROI_UTILITY@0.70");
  const std::vector<SweepPoint> points =
      SweepSummary(Sweep(), "outdoor", "EROI_UTILITY", {0.5, 0.7, 0.9});
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0].episodes, 2);
  EXPECT_DOUBLE_EQ(points[0].sr, 0.5);
  ASSERT_TRUE(points[0].path_ratio.has_value());
  EXPECT_DOUBLE_EQ(*points[0].path_ratio, 0.75);  // 30 / 40 on the one episode both found
  EXPECT_EQ(points[0].paired_episodes, 1);
  EXPECT_DOUBLE_EQ(points[0].vision_calls, 25.0);
  ASSERT_TRUE(points[0].mean_path_ratio.has_value());
  EXPECT_DOUBLE_EQ(*points[0].mean_path_ratio, 1.2);  // mean 60 m / mean 50 m
  EXPECT_EQ(points[1].episodes, 0);                   // 0.7 was not run
  EXPECT_FALSE(points[1].path_ratio.has_value());
  EXPECT_DOUBLE_EQ(points[2].sr, 1.0);
  EXPECT_DOUBLE_EQ(*points[2].path_ratio, 0.5);  // 50 / 100
}

TEST(SimBenchVlmSweepTest, PlotIsAPngOfTheStatedSize) {
  const std::string path = ::testing::TempDir() + "/vlm_sweep.png";
  ASSERT_TRUE(
      WriteVlmSweepPlot(SweepSummary(Sweep(), "outdoor", "EROI_UTILITY", {0.5, 0.9}), "test", path)
          .ok());
  const cv::Mat image = cv::imread(path);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 640);
  EXPECT_EQ(image.rows, 460);
  EXPECT_EQ(WriteVlmSweepPlot({}, "empty", path).code(), absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace semnav::sim::bench
