#pragma once

#include <cstdint>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/container/flat_hash_set.h"
#include "services/mapping/core/octomap_integrator.h"

namespace semnav::mapping {

enum class VoxelState : uint8_t { kUnknown = 0, kFree = 1, kOccupied = 2 };

// The octree's finest voxels grouped by (x, y) key column: the view the climbing algorithm
// needs (walk one column up and down) without descending the octree for every voxel.
class VoxelColumns {
 public:
  using ColumnId = uint32_t;  // x key << 16 | y key

  struct Column {
    int z_lo = 0;
    std::vector<VoxelState> states;  // states[i] is z key z_lo + i
  };

  explicit VoxelColumns(double resolution) : resolution_(resolution) {}

  // Every leaf of `tree`, pruned leaves expanded to finest voxels.
  static VoxelColumns FromOctree(const octomap::OcTree& tree);

  // Records the new state of the voxels of one scan; returns the columns it touched.
  absl::flat_hash_set<ColumnId> Apply(const std::vector<TouchedVoxel>& voxels);

  void Set(const octomap::OcTreeKey& key, VoxelState state);
  // The column, or nullptr when nothing in it was ever observed.
  const Column* Find(ColumnId column) const;
  static VoxelState StateAt(const Column& column, int z_key);

  static ColumnId IdOf(int x_key, int y_key) {
    return static_cast<ColumnId>(x_key) << 16 | static_cast<ColumnId>(y_key);
  }
  static int XKey(ColumnId id) { return static_cast<int>(id >> 16); }
  static int YKey(ColumnId id) { return static_cast<int>(id & 0xffff); }

  double resolution() const { return resolution_; }
  // Key <-> metric for the voxel centre (OctoMap's 16-level key convention).
  double KeyToCoord(int key) const { return (key - kKeyOffset + 0.5) * resolution_; }
  int CoordToKey(double coord) const;

  // Occupied voxel count per z key over all columns (for floor/ceiling estimation).
  absl::flat_hash_map<int, int64_t> OccupiedPerLevel() const;
  const absl::flat_hash_map<ColumnId, Column>& columns() const { return columns_; }

  static constexpr int kKeyOffset = 32768;

 private:
  double resolution_;
  absl::flat_hash_map<ColumnId, Column> columns_;
};

}  // namespace semnav::mapping
