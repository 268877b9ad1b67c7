#include "services/relocalization/eval/scenario.h"

#include <gtest/gtest.h>

#include "services/relocalization/core/indexed_landmarks.h"

namespace semnav::relocalization::eval {
namespace {

ScenarioParams Small() {
  ScenarioParams p;
  p.map_landmarks = 600;
  p.area_m = 40.0;
  p.keyframes = 20;
  p.lookalike_fraction = 0.25;
  return p;
}

TEST(RelocScenarioTest, SameSeedSameScenario) {
  const Scenario a = GenerateScenario(Small());
  const Scenario b = GenerateScenario(Small());
  ASSERT_EQ(a.map.size(), 600u);
  EXPECT_EQ(a.map[123].position, b.map[123].position);
  EXPECT_EQ(a.keyframes[7].observed[3].descriptor, b.keyframes[7].observed[3].descriptor);
  ScenarioParams other = Small();
  other.seed = 2;
  EXPECT_NE(GenerateScenario(other).map[123].position, a.map[123].position);
}

TEST(RelocScenarioTest, KeyframesHaveTheRequestedOutliersAndNoise) {
  const ScenarioParams p = Small();
  const Scenario s = GenerateScenario(p);
  size_t boxes = 0;
  for (bool b : s.lookalike) boxes += b;
  EXPECT_EQ(boxes, 150u);  // 25 % of 600
  double sum_sq = 0.0;
  size_t real = 0;
  for (const Keyframe& k : s.keyframes) {
    ASSERT_EQ(k.observed.size(), 50u);
    size_t false_count = 0;
    for (size_t i = 0; i < k.observed.size(); ++i) {
      if (k.truth[i] < 0) {
        ++false_count;
        continue;
      }
      const Eigen::Vector3d expected =
          k.map_from_query.inverse() * s.map[static_cast<size_t>(k.truth[i])].position;
      sum_sq += (k.observed[i].position - expected).squaredNorm();
      ++real;
    }
    EXPECT_EQ(false_count, 20u);  // 40 % outliers
  }
  // Per-axis sigma 5 cm -> mean squared 3D error 3 * 0.05^2.
  EXPECT_NEAR(sum_sq / static_cast<double>(real), 3 * 0.05 * 0.05, 0.0015);
}

TEST(RelocScenarioTest, SmokeDegradesDescriptorsByItsNorm) {
  ScenarioParams p = Small();
  p.observed_false = 0;
  p.smoke = 0.3;
  const Scenario s = GenerateScenario(p);
  double sum_sq = 0.0;
  size_t n = 0;
  for (const Keyframe& k : s.keyframes) {
    for (size_t i = 0; i < k.observed.size(); ++i) {
      const std::vector<float> clean =
          UnitDescriptor(s.map[static_cast<size_t>(k.truth[i])].descriptor);
      for (size_t d = 0; d < clean.size(); ++d) {
        const double e = k.observed[i].descriptor[d] - clean[d];
        sum_sq += e * e;
      }
      ++n;
    }
  }
  EXPECT_NEAR(sum_sq / static_cast<double>(n), 0.3 * 0.3, 0.01);  // E|noise|^2 = smoke^2
}

}  // namespace
}  // namespace semnav::relocalization::eval
