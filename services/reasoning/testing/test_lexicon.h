// The shipped lexicon, loaded once per test binary.
#pragma once

#include "services/common/lexicon/lexicon.h"

namespace semnav::reasoning {

const Lexicon& ShippedLexicon();

}  // namespace semnav::reasoning
