// The bilingual (English / Chinese) lexicon of objects, rooms, colours, spatial relations and
// instruction words: services/common/lexicon/lexicon.tsv, the one synonym table of the stack.
// The gateway parses instructions with it, the simulator checks world labels against it, and
// CanonicalTerm (canonical_term.h) takes its object and room synonyms from it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav {

enum class TermKind { kObject, kRoom, kColour, kRelation, kAction, kDeixis, kNegation, kFiller };

struct LexiconEntry {
  TermKind kind;
  std::string canonical;             // English canonical name, e.g. "couch", "left_of", "go".
  std::vector<std::string> english;  // lower-case forms, may contain spaces ("dining table").
  std::vector<std::string> chinese;
};

class Lexicon {
 public:
  // Parses the tab-separated format documented at the top of lexicon.tsv.
  static absl::StatusOr<Lexicon> Parse(std::string_view tsv);
  static absl::StatusOr<Lexicon> Load(const std::string& path);
  // The data file in the source tree (the gateway's default `lexicon_path`).
  static std::string DefaultPath();
  // lexicon.tsv as compiled into the binary: needs no file at run time.
  static const Lexicon& Embedded();

  // Entries having `form` (lower-cased English or Chinese) among their forms; empty if none.
  std::vector<const LexiconEntry*> Lookup(std::string_view form) const;
  // The first entry of `kind` having `form`, or nullptr.
  const LexiconEntry* Find(std::string_view form, TermKind kind) const;
  // The canonical object name for a free-text label ("Sofa" -> "couch"); the lower-cased label
  // itself when the lexicon does not know it.
  std::string CanonicalObject(std::string_view label) const;

  const std::vector<LexiconEntry>& entries() const { return entries_; }
  // Longest form measured in segmenter tokens, bounding the phrase matcher's window.
  std::size_t max_form_words() const { return max_form_words_; }

 private:
  std::vector<LexiconEntry> entries_;
  std::unordered_map<std::string, std::vector<std::size_t>> index_;
  std::size_t max_form_words_ = 1;
};

std::string ToLowerAscii(std::string_view text);

}  // namespace semnav
