// The shipped lexicon, loaded once per test binary.
#pragma once

#include "services/reasoning/core/lexicon.h"

namespace semnav::reasoning {

const Lexicon& ShippedLexicon();

}  // namespace semnav::reasoning
