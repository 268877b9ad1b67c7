#pragma once

#include <cstdint>
#include <string>

#include "clients/sim/core/world.h"

namespace semnav::sim {

// An indoor hall for the fly-roll robot after seed 003 section 4.2: obstacle heights drawn
// uniformly from 1-4 m (seed 003's random maps), under a 4.5 m ceiling, so some can be flown
// over and others must be rolled around; findable objects stand on the floor between them.
World FlyRollScene(const std::string& name, uint64_t seed);

}  // namespace semnav::sim
