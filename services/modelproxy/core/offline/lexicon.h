#pragma once
// Lexical normalization for the offline backend: object and place phrases in English (and the
// common Chinese names of COCO objects and rooms) map to one canonical English phrase, so
// "Sofas", "the sofa", "couch" and "沙发" all compare equal.
#include <string>
#include <vector>

#include "absl/strings/string_view.h"

namespace semnav::modelproxy::offline {

// Lower-case, '_' and '-' to spaces, punctuation dropped, leading articles dropped, each word
// singularized by suffix rules, then synonym phrases (longest first) replaced by canonical names.
std::string CanonicalTerm(absl::string_view phrase);

// Words of a canonical phrase.
std::vector<std::string> Words(const std::string& canonical);

// True if the words of `needle` occur contiguously in `haystack` (both canonical).
bool ContainsPhrase(const std::string& haystack, const std::string& needle);

struct LexicalScores {
  double modifier_match = 0.9;  // label is the target minus modifiers ("red cup" vs "cup")
  double specific_match = 0.8;  // label is a more specific kind ("cup" vs "coffee cup")
  double partial_weight = 0.7;  // times the Dice overlap of the word sets otherwise
};

// How well `label` names `target` (both canonical), in [0, 1]: 1 for equal phrases, then the
// cases of LexicalScores.
double LexicalMatch(const std::string& target, const std::string& label,
                    const LexicalScores& scores);

}  // namespace semnav::modelproxy::offline
