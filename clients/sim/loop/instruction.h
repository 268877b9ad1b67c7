// The operator instruction for a search episode, in the target name's language.
#pragma once

#include <string>

namespace semnav::sim::loop {

// "find a <target>" for an ASCII name, "找<target>" otherwise (a Chinese name).
std::string SearchInstruction(const std::string& target);

}  // namespace semnav::sim::loop
