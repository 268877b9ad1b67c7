#pragma once
// The offline backend's `decompose` task: a complex instruction ("go to the kitchen, then find
// the red cup", "先去厨房，然后找红色的杯子") split into ordered subgoals with no vendor. Clauses
// are cut at punctuation and sequence words (then / after that / 然后 / 再 ...); each clause's
// leading verb phrase gives the subgoal type, the rest its target with colours and a spatial
// relation to an anchor. Targets are canonical English where the offline lexicon knows the
// name ("沙发" -> "couch"), else kept as said, for the gateway's own resolution. The answer has
// the shape the gateway validates for any model (services/reasoning/core/subgoal_json.h):
//   {"subgoals": [{"type": "NAVIGATE", "target": "kitchen", "reason": "..."}, ...]}.
#include "absl/status/statusor.h"
#include "nlohmann/json.hpp"

namespace semnav::modelproxy::offline {

inline constexpr int kMaxOfflineSubgoals = 16;  // the gateway takes at most 16 (kMaxModelSubgoals)
inline constexpr size_t kMaxInstructionBytes = 2000;

// {"task": "decompose", "instruction": "..."}. INVALID_ARGUMENT naming "instruction" when it is
// missing, empty or too long, and when no clause names an action the rules know (the caller
// keeps its own decomposition then).
absl::StatusOr<nlohmann::json> DecomposeOffline(const nlohmann::json& task);

}  // namespace semnav::modelproxy::offline
