// Lexical normalization of object and place phrases: "Sofas", "the sofa", "couch" and "沙发" all
// become "couch". The synonyms are the object and room entries of the lexicon (lexicon.tsv); the
// rules here are only how a phrase is cut and spelled before it is looked up.
#pragma once

#include <string>
#include <string_view>

#include "absl/strings/string_view.h"

namespace semnav {

// Lower-case, '_' and '-' to spaces, punctuation dropped, leading articles dropped, each word
// singularized by suffix rules, then the lexicon's object and room forms (up to three words,
// longest first; Chinese forms as substrings, longest first) replaced by their canonical names.
std::string CanonicalTerm(absl::string_view phrase);

// True when every byte is ASCII. Lexicon phrases in ASCII are words separated by spaces; others
// (Chinese) join without spaces and match as substrings.
bool IsAscii(std::string_view text);

}  // namespace semnav
