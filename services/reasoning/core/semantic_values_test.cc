#include "services/reasoning/core/semantic_values.h"

#include "gtest/gtest.h"
#include "services/reasoning/core/region_map.h"

namespace semnav::reasoning {
namespace {

TEST(GatewaySemanticValuesTest, BayesUpdatesByHand) {
  SemanticValues values(4);  // p~ = 0.25
  EXPECT_DOUBLE_EQ(values.value(3), 0.25);
  values.ApplyVlmEvidence({0, 1});  // m = 2: 0.5 * 0.25 + 0.5
  EXPECT_DOUBLE_EQ(values.value(0), 0.625);
  values.ApplyVlmEvidence({0, 1});  // 0.5 * 0.625 + 0.5
  EXPECT_DOUBLE_EQ(values.value(1), 0.8125);
  values.ApplyRegionScore({0, 2}, 5);  // k = 2: s + (1 - s) * 5 / 10
  EXPECT_DOUBLE_EQ(values.value(0), 0.90625);
  EXPECT_DOUBLE_EQ(values.value(2), 0.625);
  values.ApplyRegionScore({2, 3}, -2);  // 0.25 + (s - 0.25) * 0.6 / 2
  EXPECT_DOUBLE_EQ(values.value(2), 0.3625);
  EXPECT_DOUBLE_EQ(values.value(3), 0.25);
  values.ApplyRegionScore({0, 1}, -5);  // strongest negative evidence: back to p~
  EXPECT_DOUBLE_EQ(values.value(0), 0.25);
  EXPECT_DOUBLE_EQ(values.value(1), 0.25);
}

TEST(GatewaySemanticValuesTest, NeverBelowThePrior) {
  SemanticValues values(10);
  for (int score = -5; score <= 5; ++score) {
    values.ApplyRegionScore({0, 1, 2}, score);
    values.ApplyVlmEvidence({score + 5 < 10 ? score + 5 : 9});
    for (double s : values.values()) {
      EXPECT_GE(s, 0.1);
      EXPECT_LE(s, 1.0);
    }
  }
}

TEST(GatewayRegionMapTest, ThirdObservationInAUnitTriggersScoring) {
  EroiGridSpec spec;
  spec.delta = 3.0;
  spec.nx = 3;
  spec.ny = 3;
  spec.nz = 0;
  const EroiGrid grid = *EroiGrid::Create(spec);
  RegionMap map(&grid, RegionMapConfig{});
  EXPECT_FALSE(map.Add({0, 0, 0}, "bike rack")->has_value());
  EXPECT_FALSE(map.Add({3, 0, 0}, "road side")->has_value());
  EXPECT_FALSE(map.Add({9, 9, 0}, "river bank")->has_value());  // another unit
  absl::StatusOr<std::optional<RegionDue>> due = map.Add({0, 3, 0}, "parking area");
  ASSERT_TRUE(due.ok() && due->has_value());
  EXPECT_EQ((*due)->region, 0);
  EXPECT_EQ((*due)->erois, (std::vector<int>{0, 1, 4, 5}));
  EXPECT_EQ((*due)->descriptions,
            (std::vector<std::string>{"bike rack", "road side", "parking area"}));
  EXPECT_FALSE(map.Add({0, 0, 0}, "again")->has_value());  // U(r) was reset
  EXPECT_EQ(map.Add({30, 0, 0}, "far away").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(map.descriptions().at(0).size(), 2u);
}

}  // namespace
}  // namespace semnav::reasoning
