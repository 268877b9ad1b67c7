// The text of lexicon.tsv, compiled in from the source tree (embedded_lexicon.cc.in).
#pragma once

#include <string_view>

namespace semnav {

std::string_view EmbeddedLexiconTsv();

}  // namespace semnav
