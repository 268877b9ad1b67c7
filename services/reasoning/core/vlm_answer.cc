#include "services/reasoning/core/vlm_answer.h"

#include <cctype>
#include <regex>
#include <string>

namespace semnav::reasoning {

std::vector<CodeDescription> ParseCodeDescriptions(std::string_view answer) {
  // Keys in any case, ASCII or full-width colon/comma (UTF-8 bytes), letter-digits-letter code.
  static const std::regex kPair(
      "[Cc][Oo][Dd][Ee]\\s*(?::|\xEF\xBC\x9A)\\s*([A-Za-z][0-9]+[A-Za-z])\\s*(?:,|\xEF\xBC\x8C)\\s*"
      "[Dd][Ee][Ss][Cc][Rr][Ii][Pp][Tt][Ii][Oo][Nn]\\s*(?::|\xEF\xBC\x9A)\\s*([^\\r\\n]*)");
  std::vector<CodeDescription> pairs;
  const std::string text(answer);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kPair);
       it != std::sregex_iterator(); ++it) {
    CodeDescription pair;
    pair.code = (*it)[1].str();
    for (char& c : pair.code) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    pair.description = (*it)[2].str();
    while (!pair.description.empty() &&
           std::isspace(static_cast<unsigned char>(pair.description.back()))) {
      pair.description.pop_back();
    }
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

}  // namespace semnav::reasoning
