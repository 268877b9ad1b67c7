#pragma once

#include <cstdint>
#include <string>

#include "absl/status/statusor.h"
#include "clients/sim/core/world.h"

namespace semnav::sim {

// Turns a HouseExpo floor plan (JSON: verts = free-space outline, room_category = room
// bounding boxes; see shared/data/floorplans/houseexpo_samples/SOURCE.txt) into a world:
// every outline edge becomes a 0.1 m wall on the outside of the free space, 2.6 m high;
// room boxes become rectangular rooms (SUNCG names lower-cased, Toilet -> bathroom,
// duplicates dropped) furnished from the room-object table, items kept inside the outline.
// NOT_FOUND for a missing file, INVALID_ARGUMENT naming the JSON key otherwise.
absl::StatusOr<World> HouseExpoWorld(const std::string& json_path, const std::string& name,
                                     uint64_t seed);

}  // namespace semnav::sim
