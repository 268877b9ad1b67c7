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
  return prior_.Relatedness(CanonicalTerm(absl::string_view(target.data(), target.size())),
                            CanonicalTerm(absl::string_view(label.data(), label.size())));
}

}  // namespace semnav::reasoning
