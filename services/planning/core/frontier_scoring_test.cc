#include "services/planning/core/frontier_scoring.h"

#include <gtest/gtest.h>

namespace semnav::planning {
namespace {

TEST(ScoreFrontiers, HandCheckedTerms) {
  // Robot at the origin; frontier A 2 m east, frontier B 4 m north.
  const std::vector<FrontierCandidate> frontiers = {{{2, 0}, 2.0}, {{0, 4}, 4.0}};
  const std::vector<Point2> visited = {{2, 1.5}};  // 1.5 m from A
  // A sofa 1 m beyond A (relevance 0.5, co-occurrence 0.8); a table due north
  // on the relation chain, 10 m away.
  const std::vector<ScoredObject> objects = {{{3, 0}, 0.5, 0.0, 0.8}, {{0, 10}, 0.0, 1.0, 0.0}};
  const std::vector<FrontierScore> s = ScoreFrontiers(frontiers, {0, 0}, visited, objects, {});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].distance, 0.5);  // 1 - 2/4
  EXPECT_DOUBLE_EQ(s[1].distance, 0.0);
  EXPECT_DOUBLE_EQ(s[0].novelty, 0.5);  // 1.5 m / 3 m
  EXPECT_DOUBLE_EQ(s[1].novelty, 1.0);  // (2,1.5)->(0,4) is 3.2 m
  EXPECT_DOUBLE_EQ(s[0].language, 0.5);
  EXPECT_DOUBLE_EQ(s[1].language, 0.0);
  // A: gradient 0.5 * cos 0 = 0.5, relation 1 * cos 90 = 0, co-occurrence 0.8.
  EXPECT_DOUBLE_EQ(s[0].gradient, 0.5);
  EXPECT_NEAR(s[0].relation, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s[0].cooccurrence, 0.8);
  EXPECT_NEAR(s[0].grounding, (0.5 + 0.0 + 0.8) / 3, 1e-12);
  // B: gradient 0.5 * cos 90 = 0, relation 1 * cos 0 = 1, nothing near.
  EXPECT_DOUBLE_EQ(s[1].relation, 1.0);
  EXPECT_NEAR(s[1].grounding, 1.0 / 3, 1e-12);
  EXPECT_NEAR(s[0].total, 0.2 * 0.5 + 0.3 * 0.5 + 0.2 * 0.5 + 0.3 * 1.3 / 3, 1e-12);
  EXPECT_NEAR(s[1].total, 0.3 * 1.0 + 0.3 * (1.0 / 3), 1e-12);
}

TEST(ScoreFrontiers, UnreachableFrontierGetsNoDistanceScore) {
  const std::vector<FrontierScore> s =
      ScoreFrontiers({{{1, 0}, -1.0}, {{2, 0}, 3.0}}, {0, 0}, {}, {}, {});
  EXPECT_DOUBLE_EQ(s[0].distance, 0.0);
  EXPECT_DOUBLE_EQ(s[1].distance, 0.0);  // the farthest reachable one
  EXPECT_DOUBLE_EQ(s[1].novelty, 1.0);   // nothing visited yet
  EXPECT_DOUBLE_EQ(s[1].total, 0.3);
}

}  // namespace
}  // namespace semnav::planning
