#include "services/reasoning/core/subgoal_json.h"

#include <string>

#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"
#include "services/reasoning/core/input_limits.h"

namespace semnav::reasoning {
namespace {

using nlohmann::json;

absl::Status Invalid(const std::string& field, const std::string& problem) {
  return absl::InvalidArgumentError(absl::StrCat(field, ": ", problem));
}

absl::StatusOr<std::string> OptionalString(const json& item, const std::string& path,
                                           const char* key) {
  if (!item.contains(key)) return std::string();
  if (!item[key].is_string()) return Invalid(absl::StrCat(path, ".", key), "must be a string");
  return item[key].get<std::string>();
}

// In [0, max]: a model's 1e300 s wait or 1e9 m stand-off is refused here,
// not turned into a command.
absl::StatusOr<double> OptionalNonNegative(const json& item, const std::string& path,
                                           const char* key, double max) {
  if (!item.contains(key)) return 0.0;
  const bool in_range =
      item[key].is_number() && item[key].get<double>() >= 0.0 && item[key].get<double>() <= max;
  if (!in_range) {
    return Invalid(absl::StrCat(path, ".", key),
                   absl::StrCat("must be a number in [0, ", max, "]"));
  }
  return item[key].get<double>();
}

absl::StatusOr<Subgoal> ParseOne(const json& item, const std::string& path) {
  if (!item.is_object()) return Invalid(path, "must be an object");
  if (!item.contains("type") || !item["type"].is_string()) {
    return Invalid(absl::StrCat(path, ".type"), "missing");
  }
  const std::string type_name = item["type"].get<std::string>();
  const std::optional<SubgoalType> type = ParseSubgoalType(type_name);
  if (!type.has_value()) {
    return Invalid(absl::StrCat(path, ".type"),
                   absl::StrCat("unknown subgoal type '", type_name, "'"));
  }
  Subgoal goal;
  goal.type = *type;
  absl::StatusOr<std::string> target = OptionalString(item, path, "target");
  if (!target.ok()) return target.status();
  if (RequiresTarget(goal.type) && target->empty()) {
    return Invalid(absl::StrCat(path, ".target"), absl::StrCat(type_name, " needs a target"));
  }
  goal.target.name = *target;
  goal.target.text = *target;
  for (auto [field, key] :
       {std::pair{&goal.target.relation, "relation"}, std::pair{&goal.target.anchor, "anchor"},
        std::pair{&goal.reason, "reason"}}) {
    absl::StatusOr<std::string> value = OptionalString(item, path, key);
    if (!value.ok()) return value.status();
    *field = *value;
  }
  if (item.contains("colours")) {
    const json& colours = item["colours"];
    if (!colours.is_array()) return Invalid(absl::StrCat(path, ".colours"), "must be an array");
    for (const json& colour : colours) {
      if (!colour.is_string()) return Invalid(absl::StrCat(path, ".colours"), "must hold strings");
      goal.target.colours.push_back(colour.get<std::string>());
    }
  }
  absl::StatusOr<double> distance = OptionalNonNegative(item, path, "distance_m", kMaxCoordinateM);
  if (!distance.ok()) return distance.status();
  absl::StatusOr<double> duration =
      OptionalNonNegative(item, path, "duration_s", kMaxCommandDurationS);
  if (!duration.ok()) return duration.status();
  goal.distance_m = *distance;
  goal.duration_s = *duration;
  return goal;
}

}  // namespace

DecomposeRequest BuildDecomposeRequest(std::string_view instruction) {
  DecomposeRequest request;
  request.prose = absl::StrCat(
      "A ground robot received this instruction (English or Chinese): \"", std::string(instruction),
      "\"\nSplit it into subgoals, in order. Types: NAVIGATE (go to a room or object), FIND "
      "(search "
      "for an object), APPROACH (close in, distance_m), VERIFY (confirm the object up close), "
      "LOOK_AROUND, "
      "EXPLORE, BACKTRACK (return to where an object was last seen), WAIT (duration_s). NAVIGATE, "
      "FIND, "
      "APPROACH and VERIFY need a target (an object or room name); give colours, and a relation "
      "(near, left_of, right_of, on, in) with its anchor object when the instruction names one.\n"
      "Answer with JSON only: {\"subgoals\": [{\"type\": \"FIND\", \"target\": \"cup\", "
      "\"colours\": [\"red\"], \"relation\": \"near\", \"anchor\": \"door\", \"reason\": "
      "\"...\"}]}");
  request.task_json = json{{"task", "decompose"}, {"instruction", std::string(instruction)}}.dump();
  return request;
}

std::string_view SubgoalsSchema() {
  return R"({"type": "object", "required": ["subgoals"], "properties": {"subgoals": {"type": "array",)"
         R"( "items": {"type": "object", "required": ["type"], "properties": {"type": {"type": "string"},)"
         R"( "target": {"type": "string"}, "colours": {"type": "array", "items": {"type": "string"}},)"
         R"( "relation": {"type": "string"}, "anchor": {"type": "string"}, "distance_m": {"type": "number"},)"
         R"( "duration_s": {"type": "number"}, "reason": {"type": "string"}}}}}})";
}

absl::StatusOr<std::vector<Subgoal>> ParseModelSubgoals(std::string_view json_text) {
  const json root = json::parse(json_text, nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded()) return Invalid("subgoals", "answer is not valid JSON");
  if (!root.is_object() || !root.contains("subgoals") || !root["subgoals"].is_array()) {
    return Invalid("subgoals", "missing array");
  }
  const json& items = root["subgoals"];
  if (items.empty()) return Invalid("subgoals", "empty");
  if (items.size() > static_cast<std::size_t>(kMaxModelSubgoals)) {
    return Invalid("subgoals", absl::StrCat("more than ", kMaxModelSubgoals, " entries"));
  }
  std::vector<Subgoal> subgoals;
  for (std::size_t i = 0; i < items.size(); ++i) {
    absl::StatusOr<Subgoal> goal = ParseOne(items[i], absl::StrCat("subgoals[", i, "]"));
    if (!goal.ok()) return goal.status();
    subgoals.push_back(*std::move(goal));
  }
  return subgoals;
}

}  // namespace semnav::reasoning
