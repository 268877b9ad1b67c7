// CooccurrencePrior over the ConceptNet AtLocation place prior (services/common/place_prior,
// data in shared/data, CC BY-SA 4.0; the same file and loader the model proxy's offline backend
// uses): two objects co-occur as much as their place distributions overlap
// (PlacePrior::Relatedness, cosine in [0, 1]; fork ~ knife > 0.6, fork ~ toilet = 0). A label the
// prior has no object for is read as a place: the target's AtLocation affinity to it (car ~ road
// 0.6, boat ~ river 0.34). Names go through CanonicalTerm ("sofa" -> "couch").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "services/common/place_prior/place_prior.h"
#include "services/reasoning/core/exploration_context.h"

namespace semnav::reasoning {

class ConceptNetCooccurrence final : public CooccurrencePrior {
 public:
  // `json_path`: conceptnet-data.json. NOT_FOUND / INVALID_ARGUMENT from the loader.
  static absl::StatusOr<ConceptNetCooccurrence> Load(const std::string& json_path);

  double Cooccurrence(std::string_view target, std::string_view label) const override;
  // The room's place distribution is the mean of its known objects' P(place | object); the
  // value is its cosine with the target's (Relatedness of the target with the room as a whole:
  // sink + oven + fridge reads as a kitchen). 0 when no object is known.
  double RoomCooccurrence(std::string_view target,
                          const std::vector<std::string>& labels) const override;

 private:
  explicit ConceptNetCooccurrence(PlacePrior prior) : prior_(std::move(prior)) {}
  PlacePrior prior_;
};

}  // namespace semnav::reasoning
