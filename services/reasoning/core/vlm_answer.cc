#include "services/reasoning/core/vlm_answer.h"

#include <array>
#include <cctype>
#include <regex>
#include <string>

#include "absl/strings/ascii.h"
#include "services/common/lexicon/canonical_term.h"

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

namespace {

bool IsWordByte(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

// Where `term` first occurs in `clause`: as whole words for ASCII terms, as a substring for others
// (CJK has no spaces); npos if absent.
size_t FindTerm(std::string_view clause, std::string_view term) {
  if (term.empty()) return std::string_view::npos;
  const bool whole_words = IsAscii(term);
  for (size_t at = clause.find(term); at != std::string_view::npos;
       at = clause.find(term, at + 1)) {
    if (!whole_words) return at;
    const size_t end = at + term.size();
    if ((at == 0 || !IsWordByte(clause[at - 1])) &&
        (end == clause.size() || !IsWordByte(clause[end]))) {
      return at;
    }
  }
  return std::string_view::npos;
}

// Clauses split at , ; . ! ? and their full-width forms (UTF-8: ， ； 。 ！ ？).
std::vector<std::string_view> Clauses(std::string_view text) {
  static constexpr std::array<std::string_view, 10> kBreaks = {",",
                                                               ";",
                                                               ".",
                                                               "!",
                                                               "?",
                                                               "\xEF\xBC\x8C",
                                                               "\xEF\xBC\x9B",
                                                               "\xE3\x80\x82",
                                                               "\xEF\xBC\x81",
                                                               "\xEF\xBC\x9F"};
  std::vector<std::string_view> clauses;
  size_t start = 0;
  for (size_t i = 0; i < text.size();) {
    size_t matched = 0;
    for (std::string_view mark : kBreaks) {
      if (text.substr(i, mark.size()) == mark) {
        matched = mark.size();
        break;
      }
    }
    if (matched == 0) {
      ++i;
      continue;
    }
    clauses.push_back(text.substr(start, i - start));
    i += matched;
    start = i;
  }
  clauses.push_back(text.substr(start));
  return clauses;
}

}  // namespace

bool DescriptionNamesTarget(std::string_view description, std::string_view target) {
  const std::string text = absl::AsciiStrToLower(std::string(description));
  std::vector<std::string> terms = {absl::AsciiStrToLower(std::string(target))};
  if (std::string canonical = absl::AsciiStrToLower(CanonicalTerm(std::string(target)));
      !canonical.empty() && canonical != terms.front()) {
    terms.push_back(std::move(canonical));
  }
  // A model often drops the operator's adjectives ("red mug" -> "a mug on the shelf"): the last
  // word of an ASCII phrase is its head noun.
  for (size_t i = 0, n = terms.size(); i < n; ++i) {
    const size_t space = terms[i].rfind(' ');
    if (space != std::string::npos && IsAscii(terms[i]))
      terms.push_back(terms[i].substr(space + 1));
  }
  // "no car here", "not a car", "without cars", "isn't", "没有汽车", "无", "不是", "未见".
  static constexpr std::array<std::string_view, 11> kNegations = {
      "no",           "not",          "without",     "none",
      "nothing",      "never",        "n't",         "\xE6\xB2\xA1\xE6\x9C\x89",
      "\xE6\x97\xA0", "\xE4\xB8\x8D", "\xE6\x9C\xAA"};
  for (std::string_view clause : Clauses(text)) {
    size_t mention = std::string_view::npos;
    for (const std::string& term : terms) mention = std::min(mention, FindTerm(clause, term));
    if (mention == std::string_view::npos) continue;
    const std::string_view before = clause.substr(0, mention);
    bool negated = false;
    for (std::string_view negation : kNegations) {
      // "n't" ends a word ("isn't"); the others are whole words (or CJK substrings).
      negated = negation == "n't" ? before.find(negation) != std::string_view::npos
                                  : FindTerm(before, negation) != std::string_view::npos;
      if (negated) break;
    }
    if (!negated) return true;
  }
  return false;
}

}  // namespace semnav::reasoning
