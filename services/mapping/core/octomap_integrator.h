#pragma once

#include <octomap/OcTree.h>

#include <Eigen/Core>
#include <vector>

#include "services/mapping/core/octree_batch_update.h"

namespace semnav::mapping {

// Inserts scans into an OcTree, equivalent to OctoMap's discretized insertPointCloud
// (free space by ray casting to each distinct endpoint voxel, endpoint voxels occupied, a voxel
// both hit and passed counts as hit) but faster: rays are cast on `threads` threads into
// per-scan voxel bitsets instead of a hash set, and the tree is updated in one Morton-ordered
// pass (ApplyVoxelUpdates) instead of one root-to-leaf descent per voxel.
class OctomapIntegrator {
 public:
  explicit OctomapIntegrator(int threads) : threads_(threads < 1 ? 1 : threads) {}

  // `points` are map-frame endpoints already limited to the sensor range; `origin` is the sensor.
  std::vector<TouchedVoxel> Integrate(octomap::OcTree& tree,
                                      const std::vector<Eigen::Vector3f>& points,
                                      const Eigen::Vector3f& origin) const;

  // Integrate's ray casting alone: one update per voxel the scan hits or passes, to give to
  // ApplyVoxelUpdates. `key_space` only converts coordinates to keys (any tree of the same
  // resolution), so this needs no lock on the map being updated.
  std::vector<VoxelUpdate> CastScan(const octomap::OcTree& key_space,
                                    const std::vector<Eigen::Vector3f>& points,
                                    const Eigen::Vector3f& origin) const;

 private:
  int threads_;
};

}  // namespace semnav::mapping
