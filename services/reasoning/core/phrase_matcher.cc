#include "services/reasoning/core/phrase_matcher.h"

#include <algorithm>

namespace semnav::reasoning {
namespace {

std::string Join(const std::vector<TextToken>& tokens, std::size_t begin, std::size_t end) {
  std::string joined;
  for (std::size_t i = begin; i < end; ++i) {
    if (i > begin && !tokens[i].is_cjk && !tokens[i - 1].is_cjk) joined += ' ';
    joined += tokens[i].text;
  }
  return joined;
}

}  // namespace

std::vector<Phrase> MatchPhrases(const std::vector<TextToken>& tokens, const Lexicon& lexicon) {
  std::vector<Phrase> phrases;
  std::size_t i = 0;
  while (i < tokens.size()) {
    if (!tokens[i].is_word) {
      // A hyphen inside an English compound ("fire-extinguisher") is not a clause break.
      if (tokens[i].text != "-") phrases.push_back({tokens[i].text, {}, true});
      ++i;
      continue;
    }
    std::size_t window_end = i + 1;
    while (window_end < tokens.size() && window_end - i < lexicon.max_form_words() &&
           (tokens[window_end].is_word || tokens[window_end].text == "-")) {
      ++window_end;
    }
    bool matched = false;
    for (std::size_t end = window_end; end > i; --end) {
      std::vector<TextToken> words;
      for (std::size_t k = i; k < end; ++k) {
        if (tokens[k].is_word) words.push_back(tokens[k]);
      }
      const std::string form = Join(words, 0, words.size());
      std::vector<const LexiconEntry*> entries = lexicon.Lookup(form);
      if (!entries.empty()) {
        phrases.push_back({form, std::move(entries), false});
        i = end;
        matched = true;
        break;
      }
    }
    if (!matched) {
      phrases.push_back({tokens[i].text, {}, false});
      ++i;
    }
  }
  return phrases;
}

}  // namespace semnav::reasoning
