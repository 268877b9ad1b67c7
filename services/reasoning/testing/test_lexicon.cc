#include "services/reasoning/testing/test_lexicon.h"

#include <cstdlib>
#include <iostream>

namespace semnav::reasoning {

const Lexicon& ShippedLexicon() {
  static const Lexicon* lexicon = [] {
    absl::StatusOr<Lexicon> loaded = Lexicon::Load(Lexicon::DefaultPath());
    if (!loaded.ok()) {
      std::cerr << loaded.status() << "\n";
      std::abort();
    }
    return new Lexicon(*std::move(loaded));
  }();
  return *lexicon;
}

}  // namespace semnav::reasoning
