#pragma once
// Object -> place commonsense prior from ConceptNet 5 /r/AtLocation edges (CC BY-SA 4.0).
// For each object, edge weights are summed per canonical place (CanonicalTerm) and normalized
// to P(place|obj). The model proxy's offline backend and the gateway's exploration co-occurrence
// both read it.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav {

inline constexpr char kPriorProvenance[] =
    "offline commonsense prior: ConceptNet 5 /r/AtLocation edges for the COCO classes "
    "(conceptnet.io), CC BY-SA 4.0";

// The prior's file inside its data folder (shared/data/object-priors/conceptnet_atlocation_coco80).
inline constexpr char kPlacePriorFile[] = "conceptnet-data.json";

class PlacePrior {
 public:
  // The data folder fixed at build time (<SEMNAV_SHARED_DATA_DIR>/object-priors/
  // conceptnet_atlocation_coco80): the default of modelproxy.offline.data_dir.
  static std::string DefaultDir();
  // DefaultDir()/conceptnet-data.json: the default of gateway.prior_path.
  static std::string DefaultPath();
  // Reads conceptnet-data.json ({class: [{start:{term}, end:{term}, weight}, ...]}). NOT_FOUND
  // if unreadable, INVALID_ARGUMENT naming the entry if malformed.
  static absl::StatusOr<PlacePrior> Load(const std::string& json_path);

  bool Knows(const std::string& object) const { return places_.count(object) != 0; }
  // P(place | object) for canonical names; 0 when either is unknown.
  double Probability(const std::string& object, const std::string& place) const;
  // P(place | object) / max_p P(p | object): 1 for the object's most typical place.
  double Affinity(const std::string& object, const std::string& place) const;
  // Cosine similarity of two objects' place distributions, in [0, 1] (objects that are found
  // in the same places are related: fork ~ knife, toilet ~ sink).
  double Relatedness(const std::string& a, const std::string& b) const;
  // Most probable places of an object, best first.
  std::vector<std::pair<std::string, double>> TopPlaces(const std::string& object, size_t k) const;
  size_t object_count() const { return places_.size(); }
  size_t edge_count() const { return edge_count_; }

 private:
  std::map<std::string, std::map<std::string, double>> places_;  // object -> place -> P
  size_t edge_count_ = 0;
};

}  // namespace semnav
