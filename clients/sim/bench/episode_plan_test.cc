#include "clients/sim/bench/episode_plan.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "clients/sim/core/test_worlds.h"

namespace semnav::sim::bench {
namespace {

World WithObject(const std::string& name, Modality modality, const std::string& label) {
  World world = testing::OpenWorld();
  world.name = name;
  world.starts[0].modality = modality;
  world.objects.push_back(
      testing::Object(label + "_1", label, testing::Box(3.0, 3.0, 0.5, 0.5, 0.8)));
  return world;
}

TEST(SimBenchEpisodePlanTest, GroupsByModalityAndAsksEveryFourthTargetInChinese) {
  const std::vector<World> worlds = {WithObject("home", Modality::kGround, "sink"),
                                     WithObject("field", Modality::kUav, "car"),
                                     WithObject("hall", Modality::kFlyRoll, "suitcase")};
  const std::vector<loop::EpisodeSpec> plan = PlanEpisodes(worlds, {4, 2, 1}, 1);
  ASSERT_EQ(plan.size(), 7u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(plan[i].world.name, "home");
    EXPECT_EQ(plan[i].target_label, "sink");
  }
  EXPECT_EQ(plan[0].target, "sink");
  EXPECT_EQ(plan[3].target, "水槽");  // i mod 4 = 3: the Chinese name, scored on the English label
  EXPECT_EQ(plan[4].world.name, "field");
  EXPECT_EQ(plan[4].world.starts[plan[4].start_index].modality, Modality::kUav);
  EXPECT_EQ(plan[5].target, "car");
  EXPECT_EQ(plan[6].world.name, "hall");
  // The same seed gives the same plan.
  const std::vector<loop::EpisodeSpec> again = PlanEpisodes(worlds, {4, 2, 1}, 1);
  for (size_t i = 0; i < plan.size(); ++i) {
    EXPECT_EQ(again[i].target, plan[i].target);
    EXPECT_EQ(again[i].start_index, plan[i].start_index);
    EXPECT_EQ(again[i].seed, plan[i].seed);
  }
}

TEST(SimBenchEpisodePlanTest, TargetsAreReachableAndNotAtTheStart) {
  // OpenWorld's start is at the origin. A chair walled in on all sides, a bottle 0.5 m from the
  // start: only the sink can be an episode's target.
  World world = WithObject("home", Modality::kGround, "sink");
  world.objects.push_back(
      testing::Object("chair_1", "chair", testing::Box(-3.0, 3.0, 0.5, 0.5, 0.8)));
  for (const auto& [x, y, sx, sy] : std::vector<std::array<double, 4>>{{-3.0, 4.0, 2.1, 0.1},
                                                                       {-3.0, 2.0, 2.1, 0.1},
                                                                       {-4.0, 3.0, 0.1, 2.1},
                                                                       {-2.0, 3.0, 0.1, 2.1}}) {
    world.obstacles.push_back(Obstacle{"wall", Rgb{}, testing::Box(x, y, sx, sy, 2.0)});
  }
  world.objects.push_back(
      testing::Object("bottle_1", "bottle", testing::Box(0.6, 0.0, 0.2, 0.2, 0.3)));
  for (const loop::EpisodeSpec& spec : PlanEpisodes({world}, {12, 0, 0}, 3))
    EXPECT_EQ(spec.target_label, "sink");
}

// A world whose only object is walled in: no draw can be scored, so the plan leaves the
// episodes out and says why instead of keeping an episode nobody can score.
TEST(SimBenchEpisodePlanTest, UnscorableEpisodesAreLeftOutAndNamed) {
  World world = testing::OpenWorld();
  world.name = "sealed";
  world.objects.push_back(
      testing::Object("chair_1", "chair", testing::Box(-3.0, 3.0, 0.5, 0.5, 0.8)));
  for (const auto& [x, y, sx, sy] : std::vector<std::array<double, 4>>{{-3.0, 4.0, 2.1, 0.1},
                                                                       {-3.0, 2.0, 2.1, 0.1},
                                                                       {-4.0, 3.0, 0.1, 2.1},
                                                                       {-2.0, 3.0, 0.1, 2.1}}) {
    world.obstacles.push_back(Obstacle{"wall", Rgb{}, testing::Box(x, y, sx, sy, 2.0)});
  }
  std::vector<std::string> unscorable;
  const std::vector<World> worlds = {world, WithObject("home", Modality::kGround, "sink")};
  const std::vector<loop::EpisodeSpec> plan = PlanEpisodes(worlds, {4, 0, 0}, 1, &unscorable);
  // Episodes 0 and 2 fall on the sealed world, 1 and 3 on the home.
  ASSERT_EQ(plan.size(), 2u);
  for (const loop::EpisodeSpec& spec : plan) EXPECT_EQ(spec.world.name, "home");
  ASSERT_EQ(unscorable.size(), 2u);
  EXPECT_NE(unscorable[0].find("indoor episode 0: sealed start 0: no scorable target"),
            std::string::npos)
      << unscorable[0];
}

TEST(SimBenchEpisodePlanTest, GroupWithoutWorldsPlansNothing) {
  const std::vector<World> worlds = {WithObject("home", Modality::kGround, "sink")};
  EXPECT_EQ(PlanEpisodes(worlds, {0, 15, 10}, 1).size(), 0u);
}

TEST(SimBenchEpisodePlanTest, PoseLossGroupsRerunTheIndoorEpisodesWithDriftAndAKidnap) {
  const std::vector<World> worlds = {WithObject("home", Modality::kGround, "sink")};
  EpisodeCounts counts{2, 0, 0};
  counts.drift = 1;
  counts.kidnapped = 2;
  const std::vector<loop::EpisodeSpec> plan = PlanEpisodes(worlds, counts, 1);
  ASSERT_EQ(plan.size(), 5u);
  const loop::EpisodeSpec& drift = plan[2];
  EXPECT_EQ(drift.report_group, "drift");
  EXPECT_EQ(drift.world.name, plan[0].world.name);
  EXPECT_EQ(drift.start_index, plan[0].start_index);
  EXPECT_EQ(drift.target, plan[0].target);
  EXPECT_TRUE(drift.sensors.odometry.enabled);
  EXPECT_TRUE(drift.localizer.enabled);
  EXPECT_EQ(drift.landmarks, "oracle");
  EXPECT_FALSE(drift.kidnap.has_value());
  EXPECT_FALSE(plan[0].sensors.odometry.enabled);  // the indoor group is unchanged
  for (int k = 3; k < 5; ++k) {
    ASSERT_TRUE(
        plan[k].kidnap.has_value());  // where to is drawn in the episode (KidnapDestination)
    EXPECT_EQ(plan[k].report_group, "kidnapped");
    EXPECT_DOUBLE_EQ(plan[k].kidnap->at_s, 60.0);
    EXPECT_DOUBLE_EQ(plan[k].kidnap->min_distance_m, 2.0);
    EXPECT_DOUBLE_EQ(plan[k].kidnap->max_distance_m, 5.0);
  }
}

}  // namespace
}  // namespace semnav::sim::bench
