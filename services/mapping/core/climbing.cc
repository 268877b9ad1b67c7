#include "services/mapping/core/climbing.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace semnav::mapping {

ColumnResult ClimbColumn(const VoxelColumns& columns, VoxelColumns::ColumnId column,
                         const ClimbingHeights& heights) {
  const int foot = columns.CoordToKey(heights.foot_m);
  const int ceiling = columns.CoordToKey(heights.ceiling_m);
  const VoxelColumns::Column* voxels = columns.Find(column);
  if (voxels == nullptr) return {ColumnClass::kUnknown, 0.0};
  int top = foot - 1;  // highest occupied voxel reached so far
  int z = foot;
  for (; z <= ceiling; ++z) {
    const VoxelState state = VoxelColumns::StateAt(*voxels, z);
    if (state == VoxelState::kFree) break;
    if (state == VoxelState::kOccupied) top = z;
  }
  // Above the voxel the climb stopped at, what hangs within the body still blocks it.
  if (heights.body_m > 0.0) {
    const int body_top = std::min(ceiling, columns.CoordToKey(heights.foot_m + heights.body_m));
    for (int k = z + 1; k <= body_top; ++k) {
      if (VoxelColumns::StateAt(*voxels, k) == VoxelState::kOccupied) top = k;
    }
  }
  if (top >= foot)
    return {z > ceiling ? ColumnClass::kStructure : ColumnClass::kObstacle,
            columns.KeyToCoord(top)};
  bool known = false;
  for (int k = foot; k <= ceiling && !known; ++k)
    known = VoxelColumns::StateAt(*voxels, k) != VoxelState::kUnknown;
  return {known ? ColumnClass::kFree : ColumnClass::kUnknown, 0.0};
}

std::optional<ClimbingHeights> EstimateHeights(const VoxelColumns& columns) {
  const absl::flat_hash_map<int, int64_t> counts = columns.OccupiedPerLevel();
  int lo = INT_MAX;
  int hi = INT_MIN;
  for (const auto& [z, n] : counts) {
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  if (counts.empty() || hi - lo < 2) return std::nullopt;
  auto count = [&](int z) {
    const auto it = counts.find(z);
    return it == counts.end() ? int64_t{0} : it->second;
  };
  auto busiest = [&](int from, int to) {
    int best = from;
    for (int z = from; z <= to; ++z) {
      if (count(z) > count(best)) best = z;
    }
    return best;
  };
  const int middle = lo + (hi - lo) / 2;
  const int floor = busiest(lo, middle);
  const int ceiling = busiest(middle + 1, hi);
  return ClimbingHeights{columns.KeyToCoord(floor + 1), columns.KeyToCoord(ceiling - 1), 0.0};
}

}  // namespace semnav::mapping
