// Slow path (seed 002, 3.2.2, System 2) in the model proxy's `match_target` contract
// (docs/algorithms/modelproxy.md): the ESCA subgraph's objects become candidates, the answer
// {"best_id", "confidence", "ranking", "offline"?} is validated and mapped to an action with the
// seed's thresholds: accept at confidence >= 0.6, ask the vision model below 0.5, explore when
// best_id is "" (target not among the objects) or the answer is not confident enough.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"
#include "services/reasoning/core/scene_graph.h"
#include "services/reasoning/core/subgoal.h"

namespace semnav::reasoning {

struct SlowPathConfig {
  double confidence_threshold = 0.6;  // slow-path answers below this are not used as goals.
  double vision_threshold = 0.5;      // below this a named candidate goes to vision verification.
  bool vision_enabled = true;
  double offline_confidence_factor =
      0.75;  // proxy answers marked "offline" (commonsense prior, no
             // model) are weighed lower, as the proxy asks callers to.
};

enum class SlowAction {
  kGoal,          // go to `object_id`.
  kVisionVerify,  // low confidence: check `object_id` with the vision model first.
  kExplore,       // not in the graph, or not confident enough: keep exploring.
};

struct SlowDecision {
  SlowAction action = SlowAction::kExplore;
  int64_t object_id = -1;
  double confidence = 0.0;    // after the offline factor
  std::string explanation;    // the best candidate's reason, if given
  bool none_matched = false;  // a valid answer whose best_id is "": no candidate is the target
};

// The two text parts of the last user message: prose for real models (instruction, target and the
// grounded scene graph as JSON) and the `match_target` task object (exactly one JSON object).
struct ResolveRequest {
  std::string prose;
  std::string task_json;
};

ResolveRequest BuildResolveRequest(std::string_view instruction, const TargetSpec& target,
                                   const SceneGraph& subgraph);

// JSON schema for RESPONSE_FORMAT_JSON_SCHEMA, as the proxy documents it.
std::string_view MatchTargetSchema();

// INVALID_ARGUMENT naming the field for malformed answers or a best_id not in `subgraph`.
absl::StatusOr<SlowDecision> ParseResolveAnswer(std::string_view answer, const SceneGraph& subgraph,
                                                const SlowPathConfig& config);

}  // namespace semnav::reasoning
