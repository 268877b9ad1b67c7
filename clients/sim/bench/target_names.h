// Chinese names the benchmark asks for, so the bilingual path of the gateway is exercised by the
// suite: the first Chinese form of the label's object in the reasoning lexicon, the same table
// the gateway parses instructions with.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace semnav::sim::bench {

// The common Chinese name of a world label ("sink" -> "水槽", "table" -> "餐桌"); nullopt for a
// label the lexicon does not know (the world loader rejects those).
std::optional<std::string> ChineseName(std::string_view label);

}  // namespace semnav::sim::bench
