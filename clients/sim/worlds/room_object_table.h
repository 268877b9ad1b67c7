#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "clients/sim/core/world.h"

// The simulator's own table of what stands in which room type, used to furnish generated
// and imported worlds. Written by hand from everyday homes and offices; deliberately NOT the
// reasoner's ConceptNet prior, so a strategy cannot score by reading its own prior back.
// Listed in docs/simulation.md.
namespace semnav::sim {

enum class Placement {
  kAgainstWall,  // back to a wall, facing the room
  kFree,         // anywhere in the room with space around it
  kOnTop,        // on top of an item labelled `on` in the same room
};

struct ItemSpec {
  std::string label;
  bool findable = true;  // true: a labelled ObjectInstance; false: an unlabelled obstacle
  Eigen::Vector3d size;  // length (along the wall), depth, height; metres
  Rgb colour;
  int min_count = 1;
  int max_count = 1;
  Placement placement = Placement::kFree;
  std::string on;  // supporting item label for kOnTop
};

// Items of a room type in placement order (supports before what stands on them); empty for
// types the table does not know (corridor, storage, ...).
const std::vector<ItemSpec>& RoomItems(std::string_view room_type);

}  // namespace semnav::sim
