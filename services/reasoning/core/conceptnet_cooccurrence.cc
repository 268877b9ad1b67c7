#include "services/reasoning/core/conceptnet_cooccurrence.h"

#include <cmath>
#include <map>

#include "services/common/lexicon/canonical_term.h"

namespace semnav::reasoning {

absl::StatusOr<ConceptNetCooccurrence> ConceptNetCooccurrence::Load(const std::string& json_path) {
  absl::StatusOr<PlacePrior> prior = PlacePrior::Load(json_path);
  if (!prior.ok()) return prior.status();
  return ConceptNetCooccurrence(*std::move(prior));
}

double ConceptNetCooccurrence::Cooccurrence(std::string_view target, std::string_view label) const {
  const std::string target_term = CanonicalTerm(absl::string_view(target.data(), target.size()));
  const std::string label_term = CanonicalTerm(absl::string_view(label.data(), label.size()));
  if (prior_.Knows(label_term)) return prior_.Relatedness(target_term, label_term);
  // A label that is no object of the prior may be a place the target is found at ("road" for
  // a car, "river" for a boat: stuff a segmenter reports).
  return prior_.Affinity(target_term, label_term);
}

double ConceptNetCooccurrence::RoomCooccurrence(std::string_view target,
                                                const std::vector<std::string>& labels) const {
  constexpr size_t kAllPlaces = 1 << 16;
  const std::string target_term = CanonicalTerm(absl::string_view(target.data(), target.size()));
  std::map<std::string, double> room;
  int known = 0;
  for (const std::string& label : labels) {
    const std::string term = CanonicalTerm(label);
    if (!prior_.Knows(term)) continue;
    ++known;
    for (const auto& [place, p] : prior_.TopPlaces(term, kAllPlaces)) room[place] += p;
  }
  if (known == 0) return 0.0;
  double dot = 0.0, target_norm = 0.0, room_norm = 0.0;
  for (const auto& [place, p] : prior_.TopPlaces(target_term, kAllPlaces)) {
    target_norm += p * p;
    auto it = room.find(place);
    if (it != room.end()) dot += p * it->second;
  }
  for (const auto& [place, w] : room) room_norm += w * w;
  if (target_norm == 0.0 || room_norm == 0.0) return 0.0;
  return dot / std::sqrt(target_norm * room_norm);  // the mean's 1/known cancels in the cosine
}

}  // namespace semnav::reasoning
