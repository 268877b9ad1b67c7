#include "clients/sim/core/label_lexicon.h"

#include "absl/strings/str_cat.h"

namespace semnav::sim {

absl::StatusOr<const reasoning::Lexicon*> LabelLexicon() {
  static const absl::StatusOr<reasoning::Lexicon>* const lexicon =
      new absl::StatusOr<reasoning::Lexicon>(
          reasoning::Lexicon::Load(reasoning::Lexicon::DefaultPath()));
  if (!lexicon->ok()) {
    return absl::FailedPreconditionError(
        absl::StrCat("object lexicon: ", lexicon->status().message()));
  }
  return &**lexicon;
}

const reasoning::LexiconEntry* ObjectEntry(std::string_view label) {
  const absl::StatusOr<const reasoning::Lexicon*> lexicon = LabelLexicon();
  if (!lexicon.ok()) return nullptr;
  return (*lexicon)->Find(label, reasoning::TermKind::kObject);
}

}  // namespace semnav::sim
