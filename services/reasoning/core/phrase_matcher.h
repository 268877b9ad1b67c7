// Greedy longest-match of lexicon forms over segmenter tokens. Dictionary segmentation does not
// always cut Chinese where the lexicon does ("卫生间" -> "卫生" + "间"), so windows of several
// tokens are joined (no space between ideographs, one space between English words) and looked up.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "services/common/lexicon/lexicon.h"
#include "services/reasoning/core/text_segmenter.h"

namespace semnav::reasoning {

struct Phrase {
  std::string surface;                       // joined form as looked up, e.g. "fire extinguisher".
  std::vector<const LexiconEntry*> entries;  // empty: a word the lexicon does not know.
  bool is_separator = false;                 // punctuation between clauses.
};

std::vector<Phrase> MatchPhrases(const std::vector<TextToken>& tokens, const Lexicon& lexicon);

}  // namespace semnav::reasoning
