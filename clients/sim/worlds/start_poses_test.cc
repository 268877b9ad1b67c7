#include "clients/sim/worlds/start_poses.h"

#include <gtest/gtest.h>

#include "clients/sim/core/test_worlds.h"

namespace semnav::sim {
namespace {

TEST(SimStartPosesTest, StartsStayWhereTheFilterAllowsAndApart) {
  const World world = testing::OpenWorld();  // 10 x 10 m, free
  Rng rng(5);
  // Only the eastern strip x > 2 (an OctoMap world passes "the scan saw floor here").
  const std::vector<StartPose> starts = ChooseStarts(
      world, Modality::kGround, 0.0, 4, rng, [](const Eigen::Vector2d& p) { return p.x() > 2.0; });
  ASSERT_EQ(starts.size(), 4u);
  for (size_t i = 0; i < starts.size(); ++i) {
    EXPECT_GT(starts[i].position.x(), 2.0);
    for (size_t j = 0; j < i; ++j) EXPECT_GE((starts[i].position - starts[j].position).norm(), 1.5);
  }
  // Nothing allowed: no starts rather than starts anywhere.
  Rng again(5);
  EXPECT_TRUE(ChooseStarts(world, Modality::kGround, 0.0, 4, again, [](const Eigen::Vector2d&) {
                return false;
              }).empty());
}

}  // namespace
}  // namespace semnav::sim
