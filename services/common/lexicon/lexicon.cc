#include "services/common/lexicon/lexicon.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "services/common/lexicon/embedded_lexicon.h"

namespace semnav {
namespace {

// Debian's Abseil is built with its own string_view type, so splitting and trimming of
// std::string_view are done here rather than with absl::StrSplit.
std::vector<std::string_view> Split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t end = text.find(separator); end != std::string_view::npos;
       start = end + 1, end = text.find(separator, start)) {
    parts.push_back(text.substr(start, end - start));
  }
  parts.push_back(text.substr(start));
  return parts;
}

std::string_view Trim(std::string_view text) {
  const std::size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

absl::StatusOr<TermKind> ParseKind(std::string_view kind) {
  static const std::pair<std::string_view, TermKind> kKinds[] = {
      {"object", TermKind::kObject},     {"room", TermKind::kRoom},
      {"colour", TermKind::kColour},     {"relation", TermKind::kRelation},
      {"action", TermKind::kAction},     {"deixis", TermKind::kDeixis},
      {"negation", TermKind::kNegation}, {"filler", TermKind::kFiller}};
  for (const auto& [name, value] : kKinds) {
    if (name == kind) return value;
  }
  return absl::InvalidArgumentError(absl::StrCat("unknown term kind '", std::string(kind), "'"));
}

std::vector<std::string> SplitForms(std::string_view field) {
  std::vector<std::string> forms;
  for (std::string_view form : Split(field, '|')) {
    form = Trim(form);
    if (!form.empty()) forms.push_back(ToLowerAscii(form));
  }
  return forms;
}

// Chinese forms are one segmenter token per character group at worst; English forms one per word.
std::size_t WordCount(const std::string& form) {
  return static_cast<std::size_t>(std::count(form.begin(), form.end(), ' ')) + 1;
}

}  // namespace

std::string ToLowerAscii(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

absl::StatusOr<Lexicon> Lexicon::Parse(std::string_view tsv) {
  Lexicon lexicon;
  int line_number = 0;
  for (std::string_view line : Split(tsv, '\n')) {
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    line = Trim(line);
    if (line.empty()) continue;
    std::vector<std::string_view> fields = Split(line, '\t');
    if (fields.size() != 4) {
      return absl::InvalidArgumentError(
          absl::StrCat("lexicon line ", line_number, ": expected 4 tab-separated fields"));
    }
    auto kind = ParseKind(fields[0]);
    if (!kind.ok()) {
      return absl::InvalidArgumentError(
          absl::StrCat("lexicon line ", line_number, ": ", kind.status().message()));
    }
    LexiconEntry entry{*kind, std::string(fields[1]), SplitForms(fields[2]), SplitForms(fields[3])};
    const std::size_t id = lexicon.entries_.size();
    for (const auto* forms : {&entry.english, &entry.chinese}) {
      for (const std::string& form : *forms) {
        lexicon.index_[form].push_back(id);
      }
    }
    for (const std::string& form : entry.english) {
      lexicon.max_form_words_ = std::max(lexicon.max_form_words_, WordCount(form));
    }
    // Chinese forms may be split by the dictionary segmenter into up to one token per character.
    for (const std::string& form : entry.chinese) {
      lexicon.max_form_words_ = std::max(lexicon.max_form_words_, form.size() / 3);
    }
    lexicon.entries_.push_back(std::move(entry));
  }
  return lexicon;
}

absl::StatusOr<Lexicon> Lexicon::Load(const std::string& path) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError(absl::StrCat("cannot open lexicon file ", path));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return Parse(buffer.str());
}

std::string Lexicon::DefaultPath() { return SEMNAV_LEXICON_TSV; }

const Lexicon& Lexicon::Embedded() {
  static const Lexicon* const lexicon = [] {
    absl::StatusOr<Lexicon> parsed = Parse(EmbeddedLexiconTsv());
    // The text is the source tree's file, which lexicon_test parses: only a broken build gets here.
    if (!parsed.ok()) {
      std::cerr << "embedded lexicon.tsv: " << parsed.status() << "\n";
      std::abort();
    }
    return new Lexicon(*std::move(parsed));
  }();
  return *lexicon;
}

std::vector<const LexiconEntry*> Lexicon::Lookup(std::string_view form) const {
  std::vector<const LexiconEntry*> found;
  auto it = index_.find(ToLowerAscii(form));
  if (it == index_.end()) return found;
  for (std::size_t id : it->second) found.push_back(&entries_[id]);
  return found;
}

const LexiconEntry* Lexicon::Find(std::string_view form, TermKind kind) const {
  for (const LexiconEntry* entry : Lookup(form)) {
    if (entry->kind == kind) return entry;
  }
  return nullptr;
}

std::string Lexicon::CanonicalObject(std::string_view label) const {
  std::string lower = ToLowerAscii(Trim(label));
  for (char& c : lower) {
    if (c == '_' || c == '-') c = ' ';
  }
  const LexiconEntry* entry = Find(lower, TermKind::kObject);
  if (entry == nullptr) entry = Find(lower, TermKind::kRoom);
  return entry != nullptr ? entry->canonical : lower;
}

}  // namespace semnav
