#include "clients/sim/loop/instruction.h"

#include <algorithm>

namespace semnav::sim::loop {

std::string SearchInstruction(const std::string& target) {
  const bool ascii = std::all_of(target.begin(), target.end(), [](char c) { return (c & 0x80) == 0; });
  return ascii ? "find a " + target : "找" + target;
}

}  // namespace semnav::sim::loop
