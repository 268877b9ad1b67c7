#include "services/mapping/core/octree_batch_update.h"

#include <cstdint>

namespace semnav::mapping {
namespace {

// Spreads the low 16 bits of v to every third bit.
uint64_t SpreadBits(uint64_t v) {
  v &= 0xffff;
  v = (v | v << 16) & 0x0000ff0000ffULL;
  v = (v | v << 8) & 0x00f00f00f00fULL;
  v = (v | v << 4) & 0x0c30c30c30c3ULL;
  v = (v | v << 2) & 0x249249249249ULL;
  return v;
}

// Child index at tree level `bit` is (code >> 3*bit) & 7 = x | y << 1 | z << 2, as in OctoMap.
uint64_t MortonCode(const octomap::OcTreeKey& k) {
  return SpreadBits(k[0]) | SpreadBits(k[1]) << 1 | SpreadBits(k[2]) << 2;
}

struct CodedUpdate {
  uint64_t code;
  const VoxelUpdate* update;
};

// LSD radix sort on the code bits that differ (scans of one frame share the high bits).
void RadixSort(std::vector<CodedUpdate>& items) {
  uint64_t varying = 0;
  for (const CodedUpdate& c : items) varying |= c.code ^ items.front().code;
  constexpr int kDigitBits = 11;
  constexpr size_t kBuckets = size_t{1} << kDigitBits;
  std::vector<CodedUpdate> scratch(items.size());
  for (int shift = 0; shift < 64 && (varying >> shift) != 0; shift += kDigitBits) {
    std::vector<size_t> start(kBuckets + 1, 0);
    for (const CodedUpdate& c : items) ++start[((c.code >> shift) & (kBuckets - 1)) + 1];
    for (size_t b = 1; b <= kBuckets; ++b) start[b] += start[b - 1];
    for (const CodedUpdate& c : items) scratch[start[(c.code >> shift) & (kBuckets - 1)]++] = c;
    items.swap(scratch);
  }
}

class BatchUpdater {
 public:
  BatchUpdater(octomap::OcTree& tree, std::vector<TouchedVoxel>& out)
      : tree_(tree), out_(out), depth_(tree.getTreeDepth()) {}

  // Returns whether `node` is a leaf after the updates.
  bool Descend(octomap::OcTreeNode* node, unsigned depth, bool node_is_new,
               const CodedUpdate* begin, const CodedUpdate* end) {
    if (depth == depth_) {
      const bool hit = begin->update->hit;
      tree_.updateNodeLogOdds(node, hit ? tree_.getProbHitLog() : tree_.getProbMissLog());
      out_.push_back({begin->update->key, tree_.isNodeOccupied(node)});
      return true;
    }
    if (!node_is_new && !tree_.nodeHasChildren(node) && Unchanged(*node, begin, end)) {
      // OctoMap's early abort: updates that cannot change a pruned leaf leave it pruned.
      const bool occupied = tree_.isNodeOccupied(node);
      for (const CodedUpdate* u = begin; u != end; ++u) out_.push_back({u->update->key, occupied});
      return true;
    }
    bool children_are_leaves = true;
    const unsigned shift = 3 * (depth_ - 1 - depth);
    for (const CodedUpdate* first = begin; first != end;) {
      const auto child = static_cast<unsigned>((first->code >> shift) & 7);
      const CodedUpdate* last = first;
      while (last != end && ((last->code >> shift) & 7) == child) ++last;
      bool child_is_new = false;
      if (!tree_.nodeChildExists(node, child)) {
        if (!tree_.nodeHasChildren(node) && !node_is_new) {
          tree_.expandNode(node);  // a pruned leaf: children inherit its value
        } else {
          tree_.createNodeChild(node, child);
          child_is_new = true;
        }
      }
      children_are_leaves &=
          Descend(tree_.getNodeChild(node, child), depth + 1, child_is_new, first, last);
      first = last;
    }
    // As updateNode: eight equal leaf children collapse into their parent (saturated free space
    // mostly), else the parent takes the max child occupancy. A touched child with children of
    // its own rules the collapse out without looking at the other seven.
    if (children_are_leaves && tree_.pruneNode(node)) return true;
    node->updateOccupancyChildren();
    return false;
  }

 private:
  // Every update of [begin, end) pushes `node` further into the clamp it is already at.
  bool Unchanged(const octomap::OcTreeNode& node, const CodedUpdate* begin,
                 const CodedUpdate* end) const {
    const float log_odds = node.getLogOdds();
    const bool at_max = log_odds >= tree_.getClampingThresMaxLog();
    const bool at_min = log_odds <= tree_.getClampingThresMinLog();
    for (const CodedUpdate* u = begin; u != end; ++u) {
      if (u->update->hit ? !at_max : !at_min) return false;
    }
    return true;
  }

  octomap::OcTree& tree_;
  std::vector<TouchedVoxel>& out_;
  unsigned depth_;
};

}  // namespace

std::vector<TouchedVoxel> ApplyVoxelUpdates(octomap::OcTree& tree,
                                            std::vector<VoxelUpdate> updates) {
  std::vector<TouchedVoxel> touched;
  if (updates.empty()) return touched;
  if (tree.getRoot() == nullptr)
    tree.updateNode(updates.front().key, 0.0f, true);  // creates the root
  std::vector<CodedUpdate> coded;
  coded.reserve(updates.size());
  for (const VoxelUpdate& u : updates) coded.push_back({MortonCode(u.key), &u});
  RadixSort(coded);
  touched.reserve(updates.size());
  BatchUpdater(tree, touched)
      .Descend(tree.getRoot(), 0, false, coded.data(), coded.data() + coded.size());
  return touched;
}

}  // namespace semnav::mapping
