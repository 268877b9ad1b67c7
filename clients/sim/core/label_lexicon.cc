#include "clients/sim/core/label_lexicon.h"

#include "absl/strings/str_cat.h"

namespace semnav::sim {

absl::StatusOr<const Lexicon*> LabelLexicon() {
  static const absl::StatusOr<Lexicon>* const lexicon =
      new absl::StatusOr<Lexicon>(Lexicon::Load(Lexicon::DefaultPath()));
  if (!lexicon->ok()) {
    return absl::FailedPreconditionError(
        absl::StrCat("object lexicon: ", lexicon->status().message()));
  }
  return &**lexicon;
}

const LexiconEntry* ObjectEntry(std::string_view label) {
  const absl::StatusOr<const Lexicon*> lexicon = LabelLexicon();
  if (!lexicon.ok()) return nullptr;
  return (*lexicon)->Find(label, TermKind::kObject);
}

}  // namespace semnav::sim
