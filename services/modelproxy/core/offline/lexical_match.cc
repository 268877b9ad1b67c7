#include "services/modelproxy/core/offline/lexical_match.h"

#include <set>

#include "absl/strings/match.h"
#include "absl/strings/str_split.h"

namespace semnav::modelproxy::offline {

std::vector<std::string> Words(const std::string& canonical) {
  return absl::StrSplit(canonical, ' ', absl::SkipEmpty());
}

bool ContainsPhrase(const std::string& haystack, const std::string& needle) {
  if (needle.empty()) return false;
  return absl::StrContains(" " + haystack + " ", " " + needle + " ");
}

double LexicalMatch(const std::string& target, const std::string& label,
                    const LexicalScores& scores) {
  if (target.empty() || label.empty()) return 0.0;
  if (target == label) return 1.0;
  if (ContainsPhrase(target, label)) return scores.modifier_match;
  if (ContainsPhrase(label, target)) return scores.specific_match;
  const std::vector<std::string> a = Words(target);
  const std::vector<std::string> b = Words(label);
  const std::set<std::string> sa(a.begin(), a.end());
  const std::set<std::string> sb(b.begin(), b.end());
  int shared = 0;
  for (const std::string& w : sa) shared += static_cast<int>(sb.count(w));
  return scores.partial_weight * 2.0 * shared / static_cast<double>(sa.size() + sb.size());
}

}  // namespace semnav::modelproxy::offline
