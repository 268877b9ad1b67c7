#pragma once
// The gateway's structured questions answered from the commonsense prior and lexical matching
// (spec: docs/algorithms/modelproxy.md, "Offline structured tasks").
#include "absl/status/statusor.h"
#include "nlohmann/json.hpp"
#include "services/common/place_prior/place_prior.h"
#include "services/modelproxy/core/offline/lexical_match.h"
#include "services/modelproxy/core/offline/open_vocabulary.h"

namespace semnav::modelproxy::offline {

struct OfflineParams {
  LexicalScores lexical;
  double relatedness_weight = 0.5;  // times the place-distribution cosine of two objects
  double place_weight = 0.8;        // times the target's affinity to a region's place name
  double min_score = 0.1;           // below this best_id is "" (nothing useful: explore)
  double description_cap = 0.7;     // a free-text mention never beats a label match
  size_t max_items = 512;           // candidates / regions per request
  // Open vocabulary (open_vocabulary.h), for targets the prior does not know: a label naming
  // the stand-in class scores this times the lexical match; an object typical of the stand-in
  // place scores this times its affinity to the place (a hint where to look, never a goal alone).
  double stand_in_class_weight = 0.85;
  double stand_in_place_weight = 0.5;
};

// Runs a task object ({"task": "match_target" | "rank_regions" | "decompose", ...}; decompose:
// offline_decompose.h). INVALID_ARGUMENT naming
// the offending field for a malformed task. The answer has task, target, best_id, confidence,
// target_in_prior (false: only lexical evidence was possible), ranking [{id, score, reason}],
// offline = true and provenance.
absl::StatusOr<nlohmann::json> RunOfflineTask(const nlohmann::json& task, const PlacePrior& prior,
                                              const OfflineParams& params);

}  // namespace semnav::modelproxy::offline
