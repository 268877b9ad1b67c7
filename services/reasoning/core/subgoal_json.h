// The model path of decomposition: the request (prose for real models, the task object
// {"task": "decompose", "instruction": ...} as the last part, docs/algorithms/modelproxy.md) and
// the validation of model-produced subgoal lists. Expected shape (the decomposition prompt asks for
// it):
//   {"subgoals": [{"type": "NAVIGATE", "target": "kitchen", "colours": ["red"],
//                  "relation": "near", "anchor": "door", "distance_m": 0.5, "duration_s": 0,
//                  "reason": "..."}]}
// Unknown types, missing targets for NAVIGATE/FIND/APPROACH/VERIFY, wrong field types or an empty
// list are rejected with INVALID_ARGUMENT naming the field, e.g. "subgoals[2].type".
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "services/reasoning/core/subgoal.h"

namespace semnav::reasoning {

inline constexpr int kMaxModelSubgoals = 16;

struct DecomposeRequest {
  std::string prose;      // the instruction and the answer contract, for real models
  std::string task_json;  // {"task": "decompose", "instruction": "..."}
};

DecomposeRequest BuildDecomposeRequest(std::string_view instruction);

// JSON schema for RESPONSE_FORMAT_JSON_SCHEMA: {"subgoals": [{type, target, ...}]}.
std::string_view SubgoalsSchema();

absl::StatusOr<std::vector<Subgoal>> ParseModelSubgoals(std::string_view json_text);

}  // namespace semnav::reasoning
