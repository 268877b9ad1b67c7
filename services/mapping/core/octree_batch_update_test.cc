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

octomap::OcTreeKey BlockKey(int i) {  // the i-th voxel of the 2 x 2 x 2 block at 32768
  return octomap::OcTreeKey(static_cast<octomap::key_type>(32768 + (i & 1)),
                            static_cast<octomap::key_type>(32768 + ((i >> 1) & 1)),
                            static_cast<octomap::key_type>(32768 + ((i >> 2) & 1)));
}

// Free space saturates at the lower clamp, and eight equal free voxels collapse into one leaf, as
// updateNode does; before, the batch pass kept every voxel of the map as its own leaf forever.
TEST(OctreeBatchUpdateTest, EightEqualChildrenArePrunedLikeUpdateNode) {
  octomap::OcTree expected(0.1);
  octomap::OcTree actual(0.1);
  std::vector<VoxelUpdate> misses;
  for (int i = 0; i < 8; ++i) misses.push_back({BlockKey(i), false});
  // Miss log-odds -0.4 per update from 0 reach the -2.0 clamp after 5 updates.
  for (int scan = 0; scan < 6; ++scan) {
    for (const VoxelUpdate& u : misses) expected.updateNode(u.key, u.hit);
    ApplyVoxelUpdates(actual, misses);
  }
  EXPECT_EQ(expected.getNumLeafNodes(), 1u);  // OctoMap's own pass pruned the block
  EXPECT_EQ(actual.getNumLeafNodes(), 1u);
  EXPECT_EQ(actual.size(), expected.size());
  const octomap::OcTreeNode* block = actual.search(BlockKey(5));
  ASSERT_NE(block, nullptr);
  EXPECT_FLOAT_EQ(block->getLogOdds(), actual.getClampingThresMinLog());
}

// A pruned saturated block that more misses cannot change stays one leaf (no expansion), and its
// voxels are still reported; a hit inside it expands it, as updateNode does.
TEST(OctreeBatchUpdateTest, ASaturatedPrunedLeafStaysPrunedUnlessAnUpdateChangesIt) {
  octomap::OcTree tree(0.1);
  std::vector<VoxelUpdate> misses;
  for (int i = 0; i < 8; ++i) misses.push_back({BlockKey(i), false});
  for (int scan = 0; scan < 6; ++scan) ApplyVoxelUpdates(tree, misses);
  const size_t pruned_size = tree.size();
  const std::vector<TouchedVoxel> touched =
      ApplyVoxelUpdates(tree, {{BlockKey(2), false}, {BlockKey(6), false}});
  ASSERT_EQ(touched.size(), 2u);
  EXPECT_FALSE(touched[0].occupied);
  EXPECT_FALSE(touched[1].occupied);
  EXPECT_EQ(tree.size(), pruned_size);
  EXPECT_EQ(tree.getNumLeafNodes(), 1u);

  const std::vector<TouchedVoxel> hit = ApplyVoxelUpdates(tree, {{BlockKey(3), true}});
  ASSERT_EQ(hit.size(), 1u);
  EXPECT_EQ(tree.getNumLeafNodes(), 8u);
  EXPECT_FLOAT_EQ(tree.search(BlockKey(3))->getLogOdds(),
                  tree.getClampingThresMinLog() + tree.getProbHitLog());
  EXPECT_FLOAT_EQ(tree.search(BlockKey(4))->getLogOdds(), tree.getClampingThresMinLog());
}

}  // namespace
}  // namespace semnav::mapping
