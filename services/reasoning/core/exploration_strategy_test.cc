#include "services/reasoning/core/exploration_strategy.h"

#include <gtest/gtest.h>

namespace semnav::reasoning {
namespace {

TEST(ExplorationStrategyTest, NamesRoundTripAndOtherTextIsRefused) {
  for (ExplorationStrategy s :
       {ExplorationStrategy::kNearestFrontier, ExplorationStrategy::kCoverageMax,
        ExplorationStrategy::kSemanticFrontier, ExplorationStrategy::kEroiUtility}) {
    EXPECT_EQ(ParseExplorationStrategy(ExplorationStrategyName(s)), s);
  }
  EXPECT_EQ(ExplorationStrategyName(ExplorationStrategy::kEroiUtility), "EROI_UTILITY");
  EXPECT_EQ(ParseExplorationStrategy("eroi_utility"), std::nullopt);
  EXPECT_EQ(ParseExplorationStrategy(""), std::nullopt);
  EXPECT_EQ(ParseExplorationStrategy("EXPLORATION_STRATEGY_EROI_UTILITY"), std::nullopt);
}

}  // namespace
}  // namespace semnav::reasoning
