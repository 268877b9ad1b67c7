// The gateway's bilingual lexicon (services/common/lexicon/lexicon.tsv) as the simulator's
// vocabulary of object labels: world files may only use its objects, and the benchmark asks for
// targets by its Chinese names.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"
#include "services/common/lexicon/lexicon.h"

namespace semnav::sim {

// The lexicon, read once from Lexicon::DefaultPath(); FAILED_PRECONDITION when unreadable.
absl::StatusOr<const Lexicon*> LabelLexicon();

// The lexicon's object entry having `label` among its English forms ("sofa" -> couch), or
// nullptr (also when the lexicon is unreadable).
const LexiconEntry* ObjectEntry(std::string_view label);

}  // namespace semnav::sim
