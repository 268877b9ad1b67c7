#include "services/reasoning/core/conceptnet_cooccurrence.h"

#include "services/modelproxy/core/offline/lexicon.h"

namespace semnav::reasoning {

absl::StatusOr<ConceptNetCooccurrence> ConceptNetCooccurrence::Load(const std::string& json_path) {
  absl::StatusOr<modelproxy::offline::PlacePrior> prior = modelproxy::offline::PlacePrior::Load(json_path);
  if (!prior.ok()) return prior.status();
  return ConceptNetCooccurrence(*std::move(prior));
}

double ConceptNetCooccurrence::Cooccurrence(std::string_view target, std::string_view label) const {
  using modelproxy::offline::CanonicalTerm;
  const std::string target_term = CanonicalTerm(absl::string_view(target.data(), target.size()));
  const std::string label_term = CanonicalTerm(absl::string_view(label.data(), label.size()));
  if (prior_.Knows(label_term)) return prior_.Relatedness(target_term, label_term);
  // A label that is no object of the prior may be a place the target is found at ("road" for
  // a car, "river" for a boat: stuff a segmenter reports).
  return prior_.Affinity(target_term, label_term);
}

}  // namespace semnav::reasoning
