#include "services/mapping/core/octree_batch_update.h"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <set>

namespace semnav::mapping {
namespace {

// The batch pass must leave exactly what one updateNode per key leaves (leaf log-odds and the
// max-child inner nodes), including when it has to expand a pruned leaf.
TEST(OctreeBatchUpdateTest, MatchesUpdateNodePerKey) {
  octomap::OcTree expected(0.1);
  octomap::OcTree actual(0.1);
  // A pruned 8-voxel free block in both trees first.
  for (octomap::OcTree* tree : {&expected, &actual}) {
    for (int i = 0; i < 8; ++i) {
      tree->updateNode(octomap::OcTreeKey(static_cast<octomap::key_type>(32768 + (i & 1)),
                                          static_cast<octomap::key_type>(32768 + ((i >> 1) & 1)),
                                          static_cast<octomap::key_type>(32768 + ((i >> 2) & 1))),
                       false);
    }
    tree->prune();
  }
  ASSERT_EQ(expected.getNumLeafNodes(), 1u);

  std::mt19937 rng(3);
  std::uniform_int_distribution<int> offset(-20, 20);
  std::set<std::array<int, 3>> seen{{0, 0, 0}};  // includes a key inside the pruned block
  std::vector<VoxelUpdate> updates{{octomap::OcTreeKey(32768, 32768, 32768), true}};
  while (updates.size() < 2000) {
    const std::array<int, 3> k{offset(rng), offset(rng), offset(rng)};
    if (!seen.insert(k).second) continue;
    updates.push_back({octomap::OcTreeKey(static_cast<octomap::key_type>(32768 + k[0]),
                                          static_cast<octomap::key_type>(32768 + k[1]),
                                          static_cast<octomap::key_type>(32768 + k[2])),
                       rng() % 3 == 0});
  }
  for (const VoxelUpdate& u : updates) expected.updateNode(u.key, u.hit);
  const std::vector<TouchedVoxel> touched = ApplyVoxelUpdates(actual, updates);

  ASSERT_EQ(touched.size(), updates.size());
  EXPECT_EQ(actual.getNumLeafNodes(), expected.getNumLeafNodes());
  for (const TouchedVoxel& t : touched) {
    const octomap::OcTreeNode* want = expected.search(t.key);
    const octomap::OcTreeNode* got = actual.search(t.key);
    ASSERT_NE(got, nullptr);
    EXPECT_FLOAT_EQ(got->getLogOdds(), want->getLogOdds());
    EXPECT_EQ(t.occupied, expected.isNodeOccupied(want));
  }
  // Inner nodes: the root holds the max child log-odds in both.
  EXPECT_FLOAT_EQ(actual.getRoot()->getLogOdds(), expected.getRoot()->getLogOdds());
}

}  // namespace
}  // namespace semnav::mapping
