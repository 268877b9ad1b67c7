#include "clients/sim/loop/instruction.h"

#include <gtest/gtest.h>

namespace semnav::sim::loop {
namespace {

TEST(SimLoopInstructionTest, SearchAreaIsTheWorldsBounds) {
  World river;
  river.bounds_min = Eigen::Vector2d(0.0, -1.0);
  river.bounds_max = Eigen::Vector2d(65.0, 47.0);
  const semnav::reasoning::v1::SearchArea area = SearchAreaOf(river);
  EXPECT_EQ(area.min_x(), 0.0);
  EXPECT_EQ(area.min_y(), -1.0);
  EXPECT_EQ(area.max_x(), 65.0);
  EXPECT_EQ(area.max_y(), 47.0);
}

}  // namespace
}  // namespace semnav::sim::loop
