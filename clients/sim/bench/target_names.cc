#include "clients/sim/bench/target_names.h"

#include "clients/sim/core/label_lexicon.h"

namespace semnav::sim::bench {

std::optional<std::string> ChineseName(std::string_view label) {
  const LexiconEntry* entry = ObjectEntry(label);
  if (entry == nullptr || entry->chinese.empty()) return std::nullopt;
  return entry->chinese.front();
}

}  // namespace semnav::sim::bench
