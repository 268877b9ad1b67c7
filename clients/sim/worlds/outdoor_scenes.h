#pragma once

#include <cstdint>

#include "clients/sim/core/world.h"

// The three outdoor UAV scenes of seed 000 (section 3.1, Fig. 7), modelled from the text:
// sizes as in the paper, layout details (tree count, where vehicles park) are ours and
// seeded. UAV starts at 1.5 m; no direct line of sight from the starts to the target area is
// NOT guaranteed (the paper's Gazebo scenes were hand-built for that).
namespace semnav::sim {

// (a) Road with vehicles, 45 x 48 m: crossing roads, parking strip, trees, bins, fallen
// poles; target "car".
World RoadVehiclesScene(uint64_t seed);
// (b) Building with vehicles, 40 x 40 m: an L-shaped building, a carport hiding a car, a
// car behind the building, fences and trees; target "car".
World BuildingVehiclesScene(uint64_t seed);
// (c) River with bridge, 65 x 47 m: a river across the scene, one bridge, roads to it,
// trees along the banks, starts on the west bank; target "bridge".
World RiverBridgeScene(uint64_t seed);

}  // namespace semnav::sim
