#pragma once

#include <vector>

#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/world.h"

namespace semnav::sim {

struct FurnishOptions {
  const Polygon2* outline = nullptr;   // free-space outline items must also stay inside
  std::vector<Eigen::Vector2d> doors;  // door centres to keep clear
  double door_clearance = 1.0;         // metres between a door centre and any item
  double wall_gap = 0.08;              // between a wall line and an item's back
  double aisle = 0.6;                  // free space around free-standing items
  int tries = 60;                      // random placements tried per item
};

// Places the room-object table's items for room.type inside room.polygon: items that fit
// without overlapping what is already in the world are appended to world->objects (findable,
// with ids "<label>_<n>") or world->obstacles (kind "furniture").
void FurnishRoom(const Room& room, const FurnishOptions& options, Rng& rng, World* world);

}  // namespace semnav::sim
