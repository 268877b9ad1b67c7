#pragma once
// How well a label names a target for the offline backend, on canonical phrases
// (CanonicalTerm, services/common/lexicon/canonical_term.h: "Sofas", "the sofa", "couch" and
// "沙发" are all "couch").
#include <string>
#include <vector>

namespace semnav::modelproxy::offline {

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
