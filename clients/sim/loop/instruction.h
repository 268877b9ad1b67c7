// The operator instruction for a search episode: the words, in the target name's language, and
// the search area.
#pragma once

#include <string>

#include "clients/sim/core/world.h"
#include "semnav/reasoning/v1/task.pb.h"

namespace semnav::sim::loop {

// "find a <target>" for an ASCII name, "找<target>" otherwise (a Chinese name).
std::string SearchInstruction(const std::string& target);

// The world's bounds: the operator bounds the search to the scene (seed 000's UAV searches a
// bounded area), so frontiers of the live map beyond it never draw the robot away.
semnav::reasoning::v1::SearchArea SearchAreaOf(const World& world);

}  // namespace semnav::sim::loop
