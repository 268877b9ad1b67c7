#include "clients/sim/loop/instruction.h"

#include <algorithm>

namespace semnav::sim::loop {

std::string SearchInstruction(const std::string& target) {
  const bool ascii =
      std::all_of(target.begin(), target.end(), [](char c) { return (c & 0x80) == 0; });
  return ascii ? "find a " + target : "找" + target;
}

semnav::reasoning::v1::SearchArea SearchAreaOf(const World& world) {
  semnav::reasoning::v1::SearchArea area;
  area.set_min_x(world.bounds_min.x());
  area.set_min_y(world.bounds_min.y());
  area.set_max_x(world.bounds_max.x());
  area.set_max_y(world.bounds_max.y());
  return area;
}

}  // namespace semnav::sim::loop
