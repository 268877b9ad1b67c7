// Parsing of the VLM's "<code, open semantics>" pairs (seed 000, eq. 13), e.g.
//   "Code: G5A, Description: 黄色共享单车旁地面区域"
// Full-width punctuation (：，) and any letter case of the keys are accepted; one pair per line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace semnav::reasoning {

struct CodeDescription {
  std::string code;         // upper-cased, e.g. "G5A"
  std::string description;  // trimmed free text
};

// Every well-formed pair in `answer`; lines that are not pairs are ignored (the prompt allows an
// empty answer when no target clue is visible).
std::vector<CodeDescription> ParseCodeDescriptions(std::string_view answer);

// True when a pair's description says the target itself is at the code ("red car parked by the
// wall", "汽车 seen here"), not a clue or a passage toward it: the target (as written, its
// canonical name, or the last word of either: "red mug" -> "mug") appears, as whole words (as a
// substring in CJK text), in a clause with no negation before it ("no car here; road ..." names
// a passage). Case-insensitive. A heuristic on free text: a wrong reading costs one look.
bool DescriptionNamesTarget(std::string_view description, std::string_view target);

}  // namespace semnav::reasoning
