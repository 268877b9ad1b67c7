#include "services/relocalization/core/landmark_matcher.h"

#include <gtest/gtest.h>

#include "services/relocalization/eval/scenario.h"

namespace semnav::relocalization {
namespace {

eval::ScenarioParams CleanScene() {
  eval::ScenarioParams p;
  p.seed = 5;
  p.map_landmarks = 300;
  p.area_m = 25.0;
  p.keyframes = 5;
  p.observed_true = 20;
  p.observed_false = 0;
  p.missing_fraction = 0.0;
  p.position_noise_m = 0.01;
  p.smoke = 0.02;
  p.lookalike_fraction = 0.0;
  return p;
}

TEST(RelocLandmarkMatcherTest, TopDescriptorLabelsAreLargestEntriesFirst) {
  const Descriptor d = {0.1f, 0.7f, 0.3f, 0.7f, 0.9f};
  EXPECT_EQ(TopDescriptorLabels(d, 3), (std::vector<int>{4, 1, 3}));  // tie 1 = 3: lower first
  EXPECT_EQ(TopDescriptorLabels(d, 1), (std::vector<int>{DescriptorLabel(d)}));
  EXPECT_EQ(TopDescriptorLabels(d, 9).size(), 5u);
  EXPECT_TRUE(TopDescriptorLabels({}, 2).empty());
}

TEST(RelocLandmarkMatcherTest, EarlyStopsAfterMCorrectMatches) {
  const eval::Scenario scene = eval::GenerateScenario(CleanScene());
  const IndexedLandmarks map(scene.map);
  const eval::Keyframe& k = scene.keyframes[0];
  const IndexedLandmarks query(k.observed);
  MatchParams params;
  params.early_stop_matches = 6;
  NeighbourhoodMatcher matcher(query, map, params);
  const std::vector<Match> first = matcher.Next(params.early_stop_matches);
  ASSERT_EQ(first.size(), 6u);
  EXPECT_FALSE(matcher.exhausted());  // stopped early: query landmarks remain
  for (const Match& m : first) EXPECT_EQ(k.truth[m.query], static_cast<int64_t>(m.map));
  // Further calls continue where the first stopped and never reuse a map landmark.
  const std::vector<Match> more = matcher.Next(100);
  EXPECT_TRUE(matcher.exhausted());
  for (const Match& m : more) {
    for (const Match& f : first) EXPECT_NE(m.map, f.map);
  }
}

TEST(RelocLandmarkMatcherTest, RematchUnderTruePoseRecoversEveryPair) {
  const eval::Scenario scene = eval::GenerateScenario(CleanScene());
  const IndexedLandmarks map(scene.map);
  const eval::Keyframe& k = scene.keyframes[1];
  const std::vector<Match> matches =
      MatchUnderPose(IndexedLandmarks(k.observed), map, k.map_from_query, MatchParams{});
  ASSERT_EQ(matches.size(), k.observed.size());
  for (const Match& m : matches) {
    EXPECT_EQ(k.truth[m.query], static_cast<int64_t>(m.map));
    EXPECT_GT(m.similarity, 0.0);
  }
}

TEST(RelocLandmarkMatcherTest, RematchUnderWrongPoseFindsNothing) {
  const eval::Scenario scene = eval::GenerateScenario(CleanScene());
  const eval::Keyframe& k = scene.keyframes[1];
  Eigen::Isometry3d wrong = k.map_from_query;
  wrong.translation() += Eigen::Vector3d(0.0, 0.0, 50.0);  // far above the map
  EXPECT_TRUE(MatchUnderPose(IndexedLandmarks(k.observed), IndexedLandmarks(scene.map), wrong,
                             MatchParams{})
                  .empty());
}

}  // namespace
}  // namespace semnav::relocalization
