#include "services/mapping/core/voxel_columns.h"

#include <cmath>

namespace semnav::mapping {

int VoxelColumns::CoordToKey(double coord) const {
  return static_cast<int>(std::floor(coord / resolution_)) + kKeyOffset;
}

VoxelColumns VoxelColumns::FromOctree(const octomap::OcTree& tree) {
  VoxelColumns columns(tree.getResolution());
  const unsigned max_depth = tree.getTreeDepth();
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    const VoxelState state = tree.isNodeOccupied(*it) ? VoxelState::kOccupied : VoxelState::kFree;
    const int span = 1 << (max_depth - it.getDepth());
    // A leaf at depth d covers span^3 finest voxels starting at its key with the low bits cleared.
    const octomap::OcTreeKey key = it.getIndexKey();
    for (int dz = 0; dz < span; ++dz) {
      for (int dy = 0; dy < span; ++dy) {
        for (int dx = 0; dx < span; ++dx) {
          columns.Set(octomap::OcTreeKey(static_cast<octomap::key_type>(key[0] + dx),
                                         static_cast<octomap::key_type>(key[1] + dy),
                                         static_cast<octomap::key_type>(key[2] + dz)),
                      state);
        }
      }
    }
  }
  return columns;
}

void VoxelColumns::Set(const octomap::OcTreeKey& key, VoxelState state) {
  Column& column = columns_[IdOf(key[0], key[1])];
  const int z = key[2];
  if (column.states.empty()) {
    column.z_lo = z;
    column.states.assign(1, state);
    return;
  }
  if (z < column.z_lo) {
    column.states.insert(column.states.begin(), static_cast<size_t>(column.z_lo - z),
                         VoxelState::kUnknown);
    column.z_lo = z;
  }
  const auto index = static_cast<size_t>(z - column.z_lo);
  if (index >= column.states.size()) column.states.resize(index + 1, VoxelState::kUnknown);
  column.states[index] = state;
}

const VoxelColumns::Column* VoxelColumns::Find(ColumnId id) const {
  const auto it = columns_.find(id);
  return it == columns_.end() ? nullptr : &it->second;
}

VoxelState VoxelColumns::StateAt(const Column& column, int z_key) {
  const int index = z_key - column.z_lo;
  if (index < 0 || index >= static_cast<int>(column.states.size())) return VoxelState::kUnknown;
  return column.states[static_cast<size_t>(index)];
}

absl::flat_hash_set<VoxelColumns::ColumnId> VoxelColumns::Apply(
    const std::vector<TouchedVoxel>& voxels) {
  absl::flat_hash_set<ColumnId> touched;
  for (const TouchedVoxel& v : voxels) {
    Set(v.key, v.occupied ? VoxelState::kOccupied : VoxelState::kFree);
    touched.insert(IdOf(v.key[0], v.key[1]));
  }
  return touched;
}

absl::flat_hash_map<int, int64_t> VoxelColumns::OccupiedPerLevel() const {
  absl::flat_hash_map<int, int64_t> counts;
  for (const auto& [id, column] : columns_) {
    for (size_t i = 0; i < column.states.size(); ++i) {
      if (column.states[i] == VoxelState::kOccupied) ++counts[column.z_lo + static_cast<int>(i)];
    }
  }
  return counts;
}

}  // namespace semnav::mapping
