#pragma once

#include <optional>

#include "services/mapping/core/voxel_columns.h"

namespace semnav::mapping {

// Foot height h_f and ceiling height h_c of the climbing algorithm (seed 003, sec. 2.1-2.2),
// metres.
struct ClimbingHeights {
  double foot_m = 0.1;
  double ceiling_m = 2.3;
  // Deviation from the seed (0 = the seed's climbing): the robot's body height above the foot.
  // An occupied voxel hanging in [h_f, h_f + body_m] blocks the column even when the climb from
  // the foot does not reach it (a chair seat on legs the sensor missed, a desk's edge): a body
  // that tall cannot pass under it. What hangs higher is still ignored (lamps, lintels).
  double body_m = 0.0;
};

enum class ColumnClass { kUnknown, kFree, kObstacle, kStructure };

struct ColumnResult {
  ColumnClass kind = ColumnClass::kUnknown;
  double top_m = 0.0;  // centre height of the highest obstacle voxel (kObstacle only)
};

// Classifies one voxel column by climbing (seed 003, Fig. 3): start at the foot voxel (h_f) and
// climb until the first free voxel. Unobserved voxels do not stop the climb: they are the inside
// of solid things (a box seen from outside) or holes a laser left in a wall; only observed free
// space proves the obstacle ended. A climb with an occupied voxel that reaches the ceiling voxel
// (h_c) is building structure (100); a shorter one is an obstacle whose top is its highest
// occupied voxel. Voxels not connected to the foot (lamps, lintels, pipes hanging from the
// ceiling) do not affect motion and are ignored, as in the seed, unless they hang within the
// body (`body_m`): then the column is an obstacle whose top is the highest occupied voxel there. A
// column without a climb but with a known voxel in [h_f, h_c] is free, otherwise unknown.
ColumnResult ClimbColumn(const VoxelColumns& columns, VoxelColumns::ColumnId column,
                         const ClimbingHeights& heights);

// Start-up estimate of h_f and h_c from the map (the seed reads the ceiling while the robot
// stands still): the floor is the most occupied z level in the lower half of the occupied
// z range, the ceiling the most occupied one in the upper half; h_f is one voxel above the
// floor voxel, h_c one voxel below the ceiling voxel. Empty if the map has fewer than 3 levels.
std::optional<ClimbingHeights> EstimateHeights(const VoxelColumns& columns);

}  // namespace semnav::mapping
