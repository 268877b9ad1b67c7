#include "services/relocalization/core/similarity.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::relocalization {
namespace {

TEST(RelocSimilarityTest, Terms) {
  EXPECT_DOUBLE_EQ(PositionSimilarity(0.0, 0.2), 1.0);
  EXPECT_NEAR(PositionSimilarity(0.2, 0.2), std::exp(-0.5), 1e-12);
  EXPECT_DOUBLE_EQ(ScaleSimilarity(0.5, 2.0), 0.25);
  EXPECT_DOUBLE_EQ(ScaleSimilarity(2.0, 0.5), 0.25);
  EXPECT_DOUBLE_EQ(ScaleSimilarity(0.0, 1.0), 0.0);
}

TEST(RelocSimilarityTest, WeightedSumWhenAllTermsPassTheirThresholds) {
  const SimilarityParams p;  // 0.4 / 0.2 / 0.4, thresholds 0.3 / 0.5 / 0.5
  EXPECT_NEAR(CombinedSimilarity({0.9, 0.8, 0.7}, p), 0.4 * 0.9 + 0.2 * 0.8 + 0.4 * 0.7, 1e-12);
}

TEST(RelocSimilarityTest, AnyTermAtOrBelowItsThresholdGivesZero) {
  const SimilarityParams p;
  EXPECT_EQ(CombinedSimilarity({0.3, 0.9, 0.9}, p), 0.0);
  EXPECT_EQ(CombinedSimilarity({0.9, 0.5, 0.9}, p), 0.0);
  EXPECT_EQ(CombinedSimilarity({0.9, 0.9, 0.49}, p), 0.0);
}

}  // namespace
}  // namespace semnav::relocalization
