#include "services/relocalization/core/relocalizer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "services/relocalization/eval/scenario.h"

namespace semnav::relocalization {
namespace {

using ::testing::HasSubstr;

eval::ScenarioParams SmallScene() {
  eval::ScenarioParams p;
  p.seed = 3;
  p.map_landmarks = 400;
  p.area_m = 30.0;
  p.keyframes = 10;
  p.observed_true = 25;
  p.observed_false = 10;
  p.position_noise_m = 0.02;
  p.lookalike_fraction = 0.1;
  return p;
}

TEST(RelocRelocalizerTest, FindsKeyframePosesInASmallScene) {
  const eval::Scenario scene = eval::GenerateScenario(SmallScene());
  const IndexedLandmarks map(scene.map);
  size_t reliable = 0;
  for (const eval::Keyframe& k : scene.keyframes) {
    const auto r = Relocalize(IndexedLandmarks(k.observed), map, RelocalizationParams{});
    ASSERT_TRUE(r.ok()) << r.status();
    if (!r->reliable) continue;
    ++reliable;
    EXPECT_LT(TranslationDifferenceM(r->map_from_query, k.map_from_query), 0.05);
    EXPECT_LT(RotationDifferenceDeg(r->map_from_query, k.map_from_query), 0.5);
    size_t correct = 0;
    for (size_t i : r->inliers) {
      const Match& m = r->matches[i];
      correct += k.truth[m.query] == static_cast<int64_t>(m.map);
    }
    EXPECT_GE(correct, 20u);                     // of 25 real landmarks in view
    EXPECT_GE(correct + 2, r->inliers.size());   // at most a couple of wrong inliers
  }
  EXPECT_GE(reliable, 9u);
}

TEST(RelocRelocalizerTest, AlignsTwoRobotMaps) {
  const eval::ScenarioParams p = SmallScene();
  const eval::Scenario scene = eval::GenerateScenario(p);
  Eigen::Isometry3d map_from_b = Eigen::Isometry3d::Identity();
  map_from_b.linear() = Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  map_from_b.translation() = Eigen::Vector3d(12.0, -4.0, 0.5);
  const eval::Keyframe robot_b =
      eval::ObserveRegion(scene, p, {15.0, 15.0, 2.0}, 6.0, map_from_b, 15, 99);
  ASSERT_GT(robot_b.observed.size(), 40u);
  const auto r = Relocalize(IndexedLandmarks(robot_b.observed), IndexedLandmarks(scene.map),
                            RelocalizationParams{});
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_TRUE(r->reliable);
  EXPECT_LT(TranslationDifferenceM(r->map_from_query, map_from_b), 0.03);
  EXPECT_LT(RotationDifferenceDeg(r->map_from_query, map_from_b), 0.3);
}

TEST(RelocRelocalizerTest, TooFewLandmarksIsNotFound) {
  const eval::Scenario scene = eval::GenerateScenario(SmallScene());
  std::vector<Landmark> two(scene.keyframes[0].observed.begin(),
                            scene.keyframes[0].observed.begin() + 2);
  const auto r = Relocalize(IndexedLandmarks(two), IndexedLandmarks(scene.map), RelocalizationParams{});
  EXPECT_EQ(r.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(r.status().message(), HasSubstr("too few landmarks"));
}

TEST(RelocRelocalizerTest, UnrelatedQueryIsNotFound) {
  eval::ScenarioParams other = SmallScene();
  other.seed = 77;  // a different world: its landmarks appear nowhere in the map
  other.lookalike_fraction = 0.0;
  const eval::Scenario map_scene = eval::GenerateScenario(SmallScene());
  const eval::Scenario query_scene = eval::GenerateScenario(other);
  const IndexedLandmarks map(map_scene.map);
  for (const eval::Keyframe& k : query_scene.keyframes) {
    const auto r = Relocalize(IndexedLandmarks(k.observed), map, RelocalizationParams{});
    EXPECT_EQ(r.status().code(), absl::StatusCode::kNotFound);
    EXPECT_THAT(r.status().message(), HasSubstr("no consistent match"));
  }
}

}  // namespace
}  // namespace semnav::relocalization
