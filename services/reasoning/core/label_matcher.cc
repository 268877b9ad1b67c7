#include "services/reasoning/core/label_matcher.h"

#include <algorithm>

namespace semnav::reasoning {
namespace {

std::vector<std::string> Words(const std::string& text) {
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(start, end - start);
    if (!word.empty() && std::find(words.begin(), words.end(), word) == words.end())
      words.push_back(std::move(word));
    start = end + 1;
  }
  return words;
}

// Whether `word` occurs in `text` delimited by spaces or the ends, without allocating.
bool HasWord(const std::string& text, const std::string& word) {
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool starts = at == 0 || text[at - 1] == ' ';
    const bool ends = at + word.size() == text.size() || text[at + word.size()] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

bool Contains(const std::vector<std::string>& values, const std::string& value) {
  return std::find(values.begin(), values.end(), value) != values.end();
}

}  // namespace

LabelMatcher::LabelMatcher(const Lexicon* lexicon, double unknown_colour_factor)
    : lexicon_(lexicon), unknown_colour_factor_(unknown_colour_factor) {}

NormalisedLabel LabelMatcher::Normalise(std::string_view label,
                                        const std::vector<std::string>& attributes) const {
  NormalisedLabel out;
  for (const std::string& attribute : attributes) {
    if (const LexiconEntry* colour = lexicon_->Find(ToLowerAscii(attribute), TermKind::kColour)) {
      out.colours.push_back(colour->canonical);
    }
  }
  // A whole-label hit first ("orange" the fruit), then peel colour words off the front ("red cup").
  std::string rest = lexicon_->CanonicalObject(label);
  if (lexicon_->Find(rest, TermKind::kObject) == nullptr) {
    std::string remaining;
    for (const std::string& word : Words(rest)) {
      const LexiconEntry* colour = lexicon_->Find(word, TermKind::kColour);
      if (colour != nullptr && remaining.empty()) {
        out.colours.push_back(colour->canonical);
      } else {
        remaining += remaining.empty() ? word : " " + word;
      }
    }
    if (!remaining.empty()) rest = lexicon_->CanonicalObject(remaining);
  }
  out.name = rest;
  return out;
}

PreparedTarget LabelMatcher::Prepare(const TargetSpec& target) const {
  PreparedTarget prepared;
  prepared.name = lexicon_->CanonicalObject(target.name);
  prepared.words = Words(prepared.name);
  for (const std::string& colour : target.colours) {
    const LexiconEntry* entry = lexicon_->Find(ToLowerAscii(colour), TermKind::kColour);
    prepared.colours.push_back(entry != nullptr ? entry->canonical : colour);
  }
  return prepared;
}

double LabelMatcher::Match(const PreparedTarget& target, const NormalisedLabel& object) const {
  double name_match = 1.0;
  if (target.name != object.name) {
    std::size_t common = 0;
    for (const std::string& word : target.words) common += HasWord(object.name, word) ? 1 : 0;
    if (common == 0) return 0.0;
    const std::size_t object_words = Words(object.name).size();
    name_match = static_cast<double>(common) /
                 static_cast<double>(target.words.size() + object_words - common);
  }
  if (target.colours.empty()) return name_match;
  if (object.colours.empty()) return name_match * unknown_colour_factor_;
  for (const std::string& colour : target.colours) {
    if (!Contains(object.colours, colour)) return 0.0;
  }
  return name_match;
}

bool LabelMatcher::SameName(std::string_view a, std::string_view b) const {
  return lexicon_->CanonicalObject(a) == lexicon_->CanonicalObject(b);
}

}  // namespace semnav::reasoning
