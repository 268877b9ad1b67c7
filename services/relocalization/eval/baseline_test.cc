#include "services/relocalization/eval/baseline.h"

#include <gtest/gtest.h>

#include "services/relocalization/core/pose_solver.h"
#include "services/relocalization/eval/scenario.h"

namespace semnav::relocalization::eval {
namespace {

TEST(RelocBaselineTest, FindsThePoseWhenDescriptorsAreDistinctive) {
  ScenarioParams p;
  p.map_landmarks = 500;
  p.area_m = 30.0;
  p.keyframes = 5;
  p.lookalike_fraction = 0.0;
  p.smoke = 0.05;
  const Scenario s = GenerateScenario(p);
  const IndexedLandmarks map(s.map);
  for (const Keyframe& k : s.keyframes) {
    const auto r =
        RelocalizeNearestDescriptorRansac(IndexedLandmarks(k.observed), map, BaselineParams{});
    ASSERT_TRUE(r.ok()) << r.status();
    EXPECT_GE(r->inliers, 25u);  // of 30 real landmarks
    EXPECT_LT(TranslationDifferenceM(r->map_from_query, k.map_from_query), 0.1);
  }
}

TEST(RelocBaselineTest, IdenticalDescriptorsDefeatIt) {
  ScenarioParams p;
  p.map_landmarks = 500;
  p.area_m = 30.0;
  p.keyframes = 5;
  p.lookalike_fraction = 1.0;  // every landmark is the same box
  p.observed_false = 0;
  const Scenario s = GenerateScenario(p);
  const IndexedLandmarks map(s.map);
  size_t found = 0;
  for (const Keyframe& k : s.keyframes) {
    found +=
        RelocalizeNearestDescriptorRansac(IndexedLandmarks(k.observed), map, BaselineParams{}).ok();
  }
  EXPECT_LE(found, 1u);
}

}  // namespace
}  // namespace semnav::relocalization::eval
