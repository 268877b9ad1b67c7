#include "services/planning/core/semantic_discount.h"

#include <gtest/gtest.h>

namespace semnav::planning {
namespace {

FrontierScore Evidence(double language, double cooccurrence) {
  FrontierScore s;
  s.language = language;
  s.cooccurrence = cooccurrence;
  return s;
}

TEST(SemanticDiscount, EvidenceIsTheStrongestCue) {
  EXPECT_DOUBLE_EQ(SemanticEvidence(Evidence(0.5, 0.8)), 0.8);
  EXPECT_DOUBLE_EQ(SemanticEvidence(Evidence(0.0, 0.0)), 0.0);
  FrontierScore s;
  s.gradient = 0.4;
  s.relation = 0.9;
  s.grounding = 0.3;  // the weighted mean is not read
  EXPECT_DOUBLE_EQ(SemanticEvidence(s), 0.9);
  s.relation = 1.7;  // out of range: clamped
  EXPECT_DOUBLE_EQ(SemanticEvidence(s), 1.0);
}

TEST(SemanticDiscount, WithoutEvidenceTheNearestReachableFrontierWins) {
  const std::vector<FrontierCandidate> candidates = {
      {{5, 0}, 5.0}, {{0, 1}, -1.0}, {{2, 0}, 2.0}, {{9, 0}, 9.0}};
  const std::vector<FrontierScore> flat(4, Evidence(0.3, 0.3));
  EXPECT_EQ(SelectDiscountedFrontier(candidates, flat, {}), 2);
  EXPECT_EQ(SelectDiscountedFrontier({{{0, 1}, -1.0}}, {FrontierScore{}}, {}), std::nullopt);
}

TEST(SemanticDiscount, EvidencePullsAsFarAsItsDiscount) {
  // Near frontier 2 m away without evidence: U = 1 / 3. A frontier with full evidence
  // (S = 1, U = 3 / (d + 1)) wins up to d < 8 m and loses beyond.
  const std::vector<FrontierScore> scores = {Evidence(0, 0), Evidence(1.0, 1.0)};
  EXPECT_EQ(SelectDiscountedFrontier({{{2, 0}, 2.0}, {{7, 0}, 7.0}}, scores, {}), 1);
  EXPECT_EQ(SelectDiscountedFrontier({{{2, 0}, 2.0}, {{9, 0}, 9.0}}, scores, {}), 0);
  // Half the evidence (S = 0.5, U = 2 / (d + 1)) wins only up to 5 m.
  const std::vector<FrontierScore> half = {Evidence(0, 0), Evidence(0.5, 0.2)};
  EXPECT_EQ(SelectDiscountedFrontier({{{2, 0}, 2.0}, {{4.5, 0}, 4.5}}, half, {}), 1);
  EXPECT_EQ(SelectDiscountedFrontier({{{2, 0}, 2.0}, {{5.5, 0}, 5.5}}, half, {}), 0);
  // Gain 0 is the nearest-frontier search whatever the evidence.
  SemanticDiscountConfig blind;
  blind.gain = 0.0;
  EXPECT_EQ(SelectDiscountedFrontier({{{2, 0}, 2.0}, {{7, 0}, 7.0}}, scores, blind), 0);
}

}  // namespace
}  // namespace semnav::planning
