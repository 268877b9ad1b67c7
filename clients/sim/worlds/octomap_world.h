#pragma once

#include <cstdint>
#include <string>

#include "absl/status/statusor.h"
#include "clients/sim/core/world.h"

namespace semnav::sim {

struct OctomapImport {
  int boxes = 0;            // merged boxes produced
  int occupied_voxels = 0;  // occupied voxels at the finest resolution (floor excluded)
  double floor_z = 0.0;     // map height taken as the floor (removed, becomes z = 0)
};

// A real building as a world: the occupied voxels of an OctoMap (.bt) above the floor layer
// become boxes, merged greedily (runs along x, then rows along y, then slabs along z);
// the floor layer (the most occupied voxel layer below 0.5 m) is dropped and z shifted so
// the floor is z = 0. The unscanned outside of the building and the edge of the bounds become
// walls, so that the robot stays in the building (docs/simulation.md, "FR-079"). Findable objects
// are added on free floor next to walls (seeded). NOT_FOUND if the file cannot be read.
absl::StatusOr<World> OctomapWorld(const std::string& bt_path, const std::string& name,
                                   uint64_t seed, OctomapImport* stats = nullptr);

}  // namespace semnav::sim
