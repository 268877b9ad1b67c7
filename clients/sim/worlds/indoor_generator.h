#pragma once

#include <cstdint>
#include <string>

#include "clients/sim/core/world.h"

namespace semnav::sim {

enum class Building { kHome, kOffice };

struct IndoorOptions {
  Building building = Building::kHome;
  double wall_height = 2.6;  // also the ceiling height
  double wall_thickness = 0.1;
  double door_width = 0.9;
  int starts = 5;  // ground-robot start poses
};

// A seeded floor plan: the footprint is split recursively (binary space partition) into
// rooms; each split wall gets one door between two rooms it separates, so every room is
// reachable; rooms get types (largest first: living room / meeting room, ...) and are
// furnished from the room-object table. Same (options, seed) -> same world.
World GenerateIndoor(const std::string& name, const IndoorOptions& options, uint64_t seed);

}  // namespace semnav::sim
