#include "services/mapping/core/octree_agreement.h"

namespace semnav::mapping {

OctreeAgreement CompareOctrees(const octomap::OcTree& reference, const octomap::OcTree& candidate) {
  double occupied_total = 0.0;
  double occupied_same = 0.0;
  double free_total = 0.0;
  double free_same = 0.0;
  const unsigned max_depth = reference.getTreeDepth();
  for (auto it = reference.begin_leafs(); it != reference.end_leafs(); ++it) {
    const double volume = static_cast<double>(1ULL << (3 * (max_depth - it.getDepth())));
    const octomap::OcTreeNode* other = candidate.search(it.getKey(), it.getDepth());
    const bool ref_occupied = reference.isNodeOccupied(*it);
    const bool same = other != nullptr && candidate.isNodeOccupied(other) == ref_occupied;
    (ref_occupied ? occupied_total : free_total) += volume;
    if (same) (ref_occupied ? occupied_same : free_same) += volume;
  }
  return {occupied_total > 0.0 ? occupied_same / occupied_total : 1.0,
          free_total > 0.0 ? free_same / free_total : 1.0};
}

}  // namespace semnav::mapping
