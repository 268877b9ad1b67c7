#include "services/common/lexicon/canonical_term.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "absl/strings/str_split.h"
#include "services/common/lexicon/lexicon.h"

namespace semnav {
namespace {

std::string Singular(const std::string& word) {
  auto ends = [&](const char* suffix) { return absl::EndsWith(word, suffix); };
  if (word.size() <= 3 || !ends("s") || ends("ss") || ends("us") || ends("is")) return word;
  const std::string stem = word.substr(0, word.size() - 1);
  if (ends("ies")) return word.substr(0, word.size() - 3) + "y";
  if (ends("lves")) return word.substr(0, word.size() - 3) + "f";
  if (ends("ives")) return word.substr(0, word.size() - 3) + "fe";
  if (ends("sses") || ends("xes") || ends("ches") || ends("shes")) {
    return word.substr(0, word.size() - 2);
  }
  return stem;
}

// Lower-case words with separators unified, articles dropped, each word singular.
std::vector<std::string> NormalizedWords(absl::string_view phrase) {
  std::string text;
  for (char c : phrase) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x80 || absl::ascii_isalnum(u)) {
      text.push_back(static_cast<char>(absl::ascii_tolower(u)));
    } else if (c != '\'') {
      text.push_back(' ');
    }
  }
  std::vector<std::string> words;
  for (absl::string_view w : absl::StrSplit(text, ' ', absl::SkipEmpty())) {
    if (words.empty() && (w == "a" || w == "an" || w == "the")) continue;
    words.push_back(Singular(std::string(w)));
  }
  return words;
}

std::string Normalized(absl::string_view phrase) {
  return absl::StrJoin(NormalizedWords(phrase), " ");
}

struct SynonymTable {
  std::map<std::string, std::string> ascii;                  // normalized phrase -> canonical
  std::vector<std::pair<std::string, std::string>> chinese;  // substring -> canonical
};

// The object and room entries of the lexicon. Canonical names map to themselves before any
// form is added, so "dining table" never becomes "dining dining table" through the "table" form
// and a compound the lexicon lists ("coffee table") is never read as a modifier plus a synonym.
const SynonymTable& Synonyms() {
  static const SynonymTable* table = [] {
    auto* t = new SynonymTable;
    std::vector<const LexiconEntry*> terms;
    for (const LexiconEntry& entry : Lexicon::Embedded().entries()) {
      if (entry.kind == TermKind::kObject || entry.kind == TermKind::kRoom) {
        terms.push_back(&entry);
      }
    }
    for (const LexiconEntry* entry : terms) {
      const std::string target = Normalized(entry->canonical);
      t->ascii.emplace(target, target);
    }
    for (const LexiconEntry* entry : terms) {
      const std::string target = Normalized(entry->canonical);
      for (const std::string& form : entry->english) t->ascii.emplace(Normalized(form), target);
      for (const std::string& form : entry->chinese) t->chinese.emplace_back(form, target);
    }
    // Longest Chinese names first so "笔记本电脑" wins over "笔记本" and "车库" over "车".
    std::stable_sort(t->chinese.begin(), t->chinese.end(),
                     [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    return t;
  }();
  return *table;
}

std::string LookupAscii(const std::string& phrase) {
  auto it = Synonyms().ascii.find(phrase);
  return it == Synonyms().ascii.end() ? "" : it->second;
}

}  // namespace

std::string CanonicalTerm(absl::string_view phrase) {
  std::string spaced(phrase);
  for (const auto& [surface, canonical] : Synonyms().chinese) {
    spaced = absl::StrReplaceAll(spaced, {{surface, " " + canonical + " "}});
  }
  const std::vector<std::string> words = NormalizedWords(spaced);
  std::vector<std::string> out;
  for (size_t i = 0; i < words.size();) {
    size_t used = 0;
    for (size_t n = std::min<size_t>(3, words.size() - i); n >= 1 && used == 0; --n) {
      const std::string candidate = absl::StrJoin(words.begin() + static_cast<long>(i),
                                                  words.begin() + static_cast<long>(i + n), " ");
      const std::string canonical = LookupAscii(candidate);
      if (!canonical.empty()) {
        out.push_back(canonical);
        used = n;
      }
    }
    if (used == 0) {
      out.push_back(words[i]);
      used = 1;
    }
    i += used;
  }
  return absl::StrJoin(out, " ");
}

bool IsAscii(std::string_view text) {
  for (char c : text) {
    if (static_cast<unsigned char>(c) >= 0x80) return false;
  }
  return true;
}

}  // namespace semnav
