#include "services/reasoning/core/topological_memory.h"

#include <cmath>

#include "gtest/gtest.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

class GatewayTopologicalMemoryTest : public ::testing::Test {
 protected:
  LabelMatcher matcher_{&ShippedLexicon(), 0.5};
};

TargetSpec Named(const char* name) {
  TargetSpec target;
  target.name = name;
  return target;
}

TEST_F(GatewayTopologicalMemoryTest, ANodeEveryTwoMetres) {
  TopologicalMemory memory(&matcher_, TopologicalMemoryConfig{});
  for (double x = 0.0; x <= 6.01; x += 0.5) memory.Update({x, 0, 0}, {}, {});
  // Nodes at x = 0, 2, 4, 6; linked in a chain.
  ASSERT_EQ(memory.nodes().size(), 4u);
  EXPECT_DOUBLE_EQ(memory.nodes()[1].position.x(), 2.0);
  EXPECT_EQ(memory.nodes()[1].neighbours, (std::vector<int64_t>{1, 3}));
  // Coming back to x = 2.3 revisits node 2.
  EXPECT_EQ(memory.Update({2.3, 0, 0}, {"sofa"}, {}), 2);
  EXPECT_EQ(memory.nodes()[1].visits, 2);
}

TEST_F(GatewayTopologicalMemoryTest, TextQueryAndBacktrack) {
  TopologicalMemory memory(&matcher_, TopologicalMemoryConfig{});
  memory.Update({0, 0, 0}, {"door"}, {});
  memory.Update({2, 0, 0}, {"red sofa", "tv"}, {});
  memory.Update({4, 0, 0}, {"chair"}, {});
  memory.Update({6, 0, 0}, {}, {});
  std::optional<MemoryMatch> sofa = memory.Query(Named("沙发"), {});
  ASSERT_TRUE(sofa.has_value());
  EXPECT_DOUBLE_EQ(sofa->position.x(), 2.0);
  EXPECT_FALSE(memory.Query(Named("toilet"), {}).has_value());
  EXPECT_DOUBLE_EQ(memory.BacktrackPosition(Named("couch"))->x(), 2.0);
  // Unknown target: back to the node before the current one.
  EXPECT_DOUBLE_EQ(memory.BacktrackPosition(Named("toilet"))->x(), 4.0);
}

TEST_F(GatewayTopologicalMemoryTest, LeastExploredSector) {
  TopologicalMemory memory(&matcher_, TopologicalMemoryConfig{});
  // Nodes east (0), north-east (1), north (2), west (4) and south (6) of the origin.
  for (Eigen::Vector3d p :
       {Eigen::Vector3d(3, 0, 0), Eigen::Vector3d(3, 3, 0), Eigen::Vector3d(0, 3, 0),
        Eigen::Vector3d(-3, 0, 0), Eigen::Vector3d(0, -3, 0)}) {
    memory.Update(p, {}, {});
  }
  // Sector 3 (north-west, 135 deg) is the first empty one.
  EXPECT_NEAR(memory.LeastExploredYaw({0, 0, 0}), 3 * M_PI / 4, 1e-12);
}

// A NaN position records nothing, and asking from one does not index outside the sectors (the
// gateway crashed there on a robot's NaN pose).
TEST_F(GatewayTopologicalMemoryTest, NonFinitePositionsAreIgnored) {
  TopologicalMemory memory(&matcher_, TopologicalMemoryConfig{});
  memory.Update({3, 0, 0}, {}, {});
  EXPECT_EQ(memory.Update(Eigen::Vector3d::Constant(std::nan("")), {}, {}), -1);
  EXPECT_EQ(memory.nodes().size(), 1u);
  const double yaw = memory.LeastExploredYaw(Eigen::Vector3d::Constant(std::nan("")));
  EXPECT_TRUE(std::isfinite(yaw));
}

TEST_F(GatewayTopologicalMemoryTest, PrunesOldestLeastVisitedPastTheLimit) {
  TopologicalMemoryConfig config;
  config.max_nodes = 500;
  TopologicalMemory memory(&matcher_, config);
  memory.Update({0, 0, 0}, {}, {});
  memory.Update({2, 0, 0}, {}, {});
  memory.Update({0, 0, 0}, {}, {});  // node 1 visited twice
  for (int i = 2; i < 500; ++i) memory.Update({2.0 * i, 0, 0}, {}, {});
  ASSERT_EQ(memory.nodes().size(), 500u);
  memory.Update({2.0 * 500, 0, 0}, {}, {});  // node 501 -> 501 nodes -> prune one
  ASSERT_EQ(memory.nodes().size(), 500u);
  // All others have 1 visit; node 1 has 2 and survives, node 2 is the oldest single-visit node.
  EXPECT_EQ(memory.nodes().front().id, 1);
  EXPECT_EQ(memory.nodes()[1].id, 3);
  for (const TopoNode& node : memory.nodes()) {
    for (int64_t n : node.neighbours) EXPECT_NE(n, 2);
  }
}

}  // namespace
}  // namespace semnav::reasoning
