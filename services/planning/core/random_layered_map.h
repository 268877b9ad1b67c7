#pragma once

#include <cstdint>

#include "services/planning/core/jump_astar.h"

namespace semnav::planning {

// The seed 003 simulation setting (sec. 4.2): a random hierarchical grid
// map, 40 x 40 m, with obstacles 1-4 m high, inside a structure border.
struct RandomLayeredMapSpec {
  double size_m = 40.0;
  double resolution_m = 0.05;
  int obstacle_count = 90;
  double min_obstacle_side_m = 0.5;
  double max_obstacle_side_m = 3.0;
  double min_obstacle_height_m = 1.0;
  double max_obstacle_height_m = 4.0;
  // Heights map to 1-99 by eq. 3 with foot h_f = 0 and this ceiling h_c.
  double ceiling_m = 5.0;
  // Disks this wide stay free around the two corner endpoints below.
  double clear_radius_m = 1.0;
  // Seed 3 of 1-3 is the default: its middle setting still flies a little,
  // like Table 2 (all three seeds show the trend, see docs).
  uint32_t seed = 3;
};

struct RandomLayeredMap {
  LayeredGrid grid;
  Cell start;  // 2 m from the lower-left corner
  Cell goal;   // 2 m from the upper-right corner
};

RandomLayeredMap MakeRandomLayeredMap(const RandomLayeredMapSpec& spec);

}  // namespace semnav::planning
