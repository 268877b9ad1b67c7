#pragma once

#include <octomap/OcTree.h>

#include <vector>

namespace semnav::mapping {

// A voxel changed by one scan and its occupancy after the update.
struct TouchedVoxel {
  octomap::OcTreeKey key;
  bool occupied = false;
};

// One measurement for a voxel: hit (occupied) or passed by a ray (free).
struct VoxelUpdate {
  octomap::OcTreeKey key;
  bool hit = false;
};

// Applies one hit/miss update per voxel in a single depth-first pass. The keys are sorted into
// OctoMap's child order (Morton order), so each tree node on their paths is visited once instead of
// once per key as with updateNode. As non-lazy updateNode does: a pruned leaf that the updates
// cannot change (all hits at the upper clamp, or all misses at the lower) stays pruned, any other
// is expanded; a node whose eight children end as equal leaves is pruned, and every other inner
// node on a touched path is refreshed to its max-child occupancy.
// Returns each voxel with its occupancy after the update. Keys must be distinct.
std::vector<TouchedVoxel> ApplyVoxelUpdates(octomap::OcTree& tree,
                                            std::vector<VoxelUpdate> updates);

}  // namespace semnav::mapping
