#include "services/reasoning/core/slow_answer.h"

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "nlohmann/json.hpp"
#include "services/common/status/field_error.h"
#include "services/reasoning/core/scene_graph_json.h"

namespace semnav::reasoning {
namespace {

// "red cup near door": what the candidates are matched against.
std::string TargetText(const TargetSpec& target) {
  std::string text = absl::StrJoin(target.colours, " ");
  absl::StrAppend(&text, text.empty() ? "" : " ", target.name);
  if (!target.relation.empty()) absl::StrAppend(&text, " ", target.relation, " ", target.anchor);
  return text;
}

}  // namespace

ResolveRequest BuildResolveRequest(std::string_view instruction, const TargetSpec& target,
                                   const SceneGraph& subgraph) {
  ResolveRequest request;
  request.prose = absl::StrCat(
      "You help a robot find objects. Instruction: \"", std::string(instruction), "\". Target: \"",
      target.text.empty() ? TargetText(target) : target.text,
      "\".\nScene graph (objects with id, label, position in metres, detector score; relations as "
      "[subject, relation, object]; regions):\n",
      SceneGraphToPromptJson(subgraph),
      "\nRank the candidates of the task below by how well they match the target; best_id \"\" "
      "when "
      "none of them is the target.");
  nlohmann::json candidates = nlohmann::json::array();
  for (const SceneObject& object : subgraph.objects) {
    std::string description = absl::StrJoin(object.attributes, " ");
    for (const SceneRelation& relation : subgraph.relations) {
      if (relation.subject_id != object.id) continue;
      const SceneObject* other = subgraph.FindObject(relation.object_id);
      if (other != nullptr)
        absl::StrAppend(&description, description.empty() ? "" : ", ", relation.relation, " ",
                        other->label);
    }
    candidates.push_back(
        {{"id", absl::StrCat(object.id)}, {"label", object.label}, {"description", description}});
  }
  request.task_json = nlohmann::json{
      {"task", "match_target"},
      {"target", TargetText(target)},
      {"candidates",
       candidates}}.dump();
  return request;
}

std::string_view MatchTargetSchema() {
  return R"({"type": "object", "required": ["best_id", "confidence", "ranking"],)"
         R"( "properties": {"best_id": {"type": "string"}, "confidence": {"type": "number"},)"
         R"( "ranking": {"type": "array", "items": {"type": "object", "required": ["id", "score"],)"
         R"( "properties": {"id": {"type": "string"}, "score": {"type": "number"},)"
         R"( "reason": {"type": "string"}}}}}})";
}

absl::StatusOr<SlowDecision> ParseResolveAnswer(std::string_view answer, const SceneGraph& subgraph,
                                                const SlowPathConfig& config) {
  const nlohmann::json root = nlohmann::json::parse(answer, nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) {
    return InvalidField("answer", "not a JSON object");
  }
  if (!root.contains("best_id") || !root["best_id"].is_string()) {
    return InvalidField("best_id", "must be a string");
  }
  if (!root.contains("confidence") || !root["confidence"].is_number() ||
      root["confidence"].get<double>() < 0.0 || root["confidence"].get<double>() > 1.0) {
    return InvalidField("confidence", "must be a number in [0, 1]");
  }
  if (root.contains("offline") && !root["offline"].is_boolean()) {
    return InvalidField("offline", "must be a boolean");
  }
  SlowDecision decision;
  decision.confidence = root["confidence"].get<double>();
  if (root.value("offline", false)) decision.confidence *= config.offline_confidence_factor;
  const std::string best = root["best_id"].get<std::string>();
  if (root.contains("ranking") && root["ranking"].is_array()) {
    for (const nlohmann::json& item : root["ranking"]) {
      // value("id", "") throws for an id that is not a string: check the type first.
      if (item.is_object() && item.contains("id") && item["id"].is_string() &&
          item["id"].get<std::string>() == best && item.contains("reason") &&
          item["reason"].is_string()) {
        decision.explanation = item["reason"].get<std::string>();
      }
    }
  }
  if (best.empty()) {  // not among the candidates: explore
    decision.none_matched = true;
    return decision;
  }
  if (!absl::SimpleAtoi(best, &decision.object_id) ||
      subgraph.FindObject(decision.object_id) == nullptr) {
    return InvalidField("best_id", absl::StrCat("'", Preview(best), "' is not a candidate"));
  }
  if (decision.confidence >= config.confidence_threshold) {
    decision.action = SlowAction::kGoal;
  } else if (decision.confidence < config.vision_threshold && config.vision_enabled) {
    decision.action = SlowAction::kVisionVerify;
  }
  return decision;
}

}  // namespace semnav::reasoning
