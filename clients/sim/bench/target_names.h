// Chinese names the benchmark asks for, the simulator's own table of everyday names for its
// object labels, so the bilingual path of the gateway is exercised by the suite.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace semnav::sim::bench {

// The common Chinese name of a world label ("sink" -> "水槽"); nullopt for labels without one here.
std::optional<std::string> ChineseName(std::string_view label);

}  // namespace semnav::sim::bench
