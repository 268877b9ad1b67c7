#include "clients/sim/core/episode_metrics.h"

#include <gtest/gtest.h>

#include "clients/sim/core/test_worlds.h"

namespace semnav::sim {
namespace {

using testing::Box;

TEST(SimEpisodeMetricsTest, SplByHand) {
  EXPECT_DOUBLE_EQ(SuccessWeightedPathLength(true, 5.0, 10.0), 0.5);
  EXPECT_DOUBLE_EQ(SuccessWeightedPathLength(true, 5.0, 5.0), 1.0);
  // A path shorter than "shortest" (target reached within the radius early) caps at 1.
  EXPECT_DOUBLE_EQ(SuccessWeightedPathLength(true, 5.0, 4.0), 1.0);
  EXPECT_DOUBLE_EQ(SuccessWeightedPathLength(false, 5.0, 5.0), 0.0);
}

TEST(SimEpisodeMetricsTest, StopScoredAgainstNearestInstanceFootprint) {
  World world = testing::OpenWorld();
  world.objects.push_back(testing::Object("a", "chair", Box(3.0, 0.0, 1.0, 1.0, 1.0)));
  world.objects.push_back(testing::Object("b", "chair", Box(-4.0, 0.0, 1.0, 1.0, 1.0)));
  world.objects.push_back(testing::Object("c", "bed", Box(0.0, 1.0, 2.0, 1.0, 0.5)));
  // Nearest chair face is x = 2.5: 0.9 m from x = 1.6.
  StopOutcome stop = ScoreStop(world, "chair", {1.6, 0.0}, true);
  EXPECT_NEAR(stop.distance_to_goal_m, 0.9, 1e-12);
  EXPECT_TRUE(stop.success);
  stop = ScoreStop(world, "chair", {1.4, 0.0}, true);
  EXPECT_NEAR(stop.distance_to_goal_m, 1.1, 1e-12);
  EXPECT_FALSE(stop.success);
  EXPECT_TRUE(ScoreStop(world, "chair", {1.4, 0.0}, true, 1.5).success);
  // Close enough but no stop issued: not a success.
  EXPECT_FALSE(ScoreStop(world, "chair", {2.0, 0.0}, false).success);
  EXPECT_TRUE(std::isinf(DistanceToNearestInstance(world, "sofa", {0, 0})));
}

TEST(SimEpisodeMetricsTest, AggregatesPerStrategyByHand) {
  auto record = [](std::string strategy, bool success, double l, double p, double d, double t,
                   double energy, int calls, int resolved, int fast) {
    EpisodeRecord r;
    r.strategy = std::move(strategy);
    r.success = success;
    r.shortest_path_m = l;
    r.path_m = p;
    r.distance_to_goal_m = d;
    r.time_s = t;
    r.energy_j = energy;
    r.model_calls = calls;
    r.goals_resolved = resolved;
    r.goals_fast_path = fast;
    return r;
  };
  const std::vector<EpisodeRecord> records = {
      record("semantic", true, 4, 8, 0.5, 10, 100, 2, 4, 3),
      record("frontier", true, 6, 6, 0.8, 20, 0, 0, 0, 0),
      record("semantic", false, 3, 9, 3.5, 30, 300, 4, 1, 0)};
  const auto summaries = SummariseByStrategy(records);
  ASSERT_EQ(summaries.size(), 2u);
  const StrategySummary& s = summaries[0];
  EXPECT_EQ(s.strategy, "semantic");
  EXPECT_EQ(s.episodes, 2);
  EXPECT_DOUBLE_EQ(s.sr, 0.5);
  EXPECT_DOUBLE_EQ(s.spl, (0.5 + 0.0) / 2);
  EXPECT_DOUBLE_EQ(s.dtg_m, 2.0);
  EXPECT_DOUBLE_EQ(s.path_m, 8.5);
  EXPECT_DOUBLE_EQ(s.time_s, 20.0);
  EXPECT_DOUBLE_EQ(s.energy_j, 200.0);
  EXPECT_DOUBLE_EQ(s.model_calls, 3.0);
  EXPECT_DOUBLE_EQ(s.fast_path_share, 3.0 / 5.0);
  EXPECT_DOUBLE_EQ(summaries[1].spl, 1.0);
  EXPECT_DOUBLE_EQ(summaries[1].fast_path_share, 0.0);
}

}  // namespace
}  // namespace semnav::sim
