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

}  // namespace semnav::reasoning
