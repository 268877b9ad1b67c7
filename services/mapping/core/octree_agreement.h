#pragma once

#include <octomap/OcTree.h>

namespace semnav::mapping {

// Share of the reference tree's known volume that `candidate` classifies the same way.
struct OctreeAgreement {
  double occupied = 0.0;  // of the reference's occupied volume, fraction occupied in candidate
  double free = 0.0;      // of the reference's free volume, fraction free in candidate
};

// Compares leaf by leaf (volume-weighted, so pruned leaves count for all voxels they hold).
// Voxels unknown in the candidate count as disagreement.
OctreeAgreement CompareOctrees(const octomap::OcTree& reference, const octomap::OcTree& candidate);

}  // namespace semnav::mapping
