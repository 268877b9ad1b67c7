#include "services/reasoning/core/task_decomposer.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "services/reasoning/core/subgoal_json.h"

namespace semnav::reasoning {
namespace {

bool Has(const Clause& clause, std::string_view action) {
  return std::find(clause.actions.begin(), clause.actions.end(), action) != clause.actions.end();
}

Subgoal Make(SubgoalType type, const TargetSpec& target, std::string reason) {
  Subgoal goal;
  goal.type = type;
  goal.target = target;
  goal.reason = std::move(reason);
  return goal;
}

}  // namespace

TaskDecomposer::TaskDecomposer(InstructionParser parser, DecomposerConfig config)
    : parser_(std::move(parser)), config_(config) {}

// Seed 002 examples: "去厨房找红色杯子" -> NAVIGATE(厨房) FIND LOOK_AROUND APPROACH VERIFY;
// "去红色灭火器旁边" -> NAVIGATE APPROACH VERIFY.
std::vector<Subgoal> TaskDecomposer::FromClause(const Clause& clause) const {
  std::vector<Subgoal> out;
  const bool find = Has(clause, "find") || Has(clause, "look_around");
  if (!clause.room.empty() && !Has(clause, "backtrack")) {
    out.push_back(Make(SubgoalType::kNavigate, clause.room, "go to the named room"));
  }
  if (Has(clause, "backtrack")) {
    const TargetSpec& where = clause.objects.empty() ? clause.room : clause.objects.front();
    out.push_back(Make(SubgoalType::kBacktrack, where, "return to where it was last seen"));
  }
  if (Has(clause, "explore"))
    out.push_back(Make(SubgoalType::kExplore, {}, "explore unknown space"));
  for (const TargetSpec& object : clause.objects) {
    if (Has(clause, "backtrack")) break;
    if (find) {
      out.push_back(Make(SubgoalType::kFind, object, "search the scene graph"));
      out.push_back(Make(SubgoalType::kLookAround, {}, "scan for the target"));
    } else if (!Has(clause, "approach")) {
      out.push_back(Make(SubgoalType::kNavigate, object, "go to the target"));
    }
    Subgoal approach = Make(SubgoalType::kApproach, object, "close the last metres");
    approach.distance_m = config_.approach_distance_m;
    out.push_back(approach);
    out.push_back(Make(SubgoalType::kVerify, object, "confirm the target up close"));
  }
  if (clause.objects.empty() && Has(clause, "look_around")) {
    out.push_back(Make(SubgoalType::kLookAround, {}, "look around"));
  }
  if (Has(clause, "wait")) out.push_back(Make(SubgoalType::kWait, {}, "wait"));
  return out;
}

std::vector<Subgoal> TaskDecomposer::FromClauses(const std::vector<Clause>& clauses) const {
  std::vector<Subgoal> out;
  for (const Clause& clause : clauses) {
    std::vector<Subgoal> part = FromClause(clause);
    out.insert(out.end(), part.begin(), part.end());
  }
  return out;
}

Decomposition TaskDecomposer::Decompose(std::string_view instruction) {
  const ParsedInstruction parsed = parser_.Parse(instruction);
  Decomposition result;
  result.subgoals = FromClauses(parsed.clauses);
  std::size_t targets = 0;
  for (const Clause& clause : parsed.clauses) targets += clause.objects.size();
  result.complex = parsed.clauses.size() > 1 || targets > 1 ||
                   parsed.unknown_words() > config_.max_simple_unknown_words ||
                   result.subgoals.empty();
  return result;
}

std::vector<Subgoal> TaskDecomposer::CompleteFinds(std::vector<Subgoal> subgoals) const {
  std::vector<Subgoal> out;
  for (std::size_t i = 0; i < subgoals.size(); ++i) {
    out.push_back(subgoals[i]);
    const TargetSpec& found = subgoals[i].target;
    if (subgoals[i].type != SubgoalType::kFind || found.is_room || found.name.empty()) continue;
    const bool completed = std::any_of(
        subgoals.begin() + static_cast<std::ptrdiff_t>(i) + 1, subgoals.end(),
        [&](const Subgoal& later) {
          return (later.type == SubgoalType::kApproach || later.type == SubgoalType::kVerify) &&
                 later.target.name == found.name;
        });
    if (completed) continue;
    Subgoal approach = Make(SubgoalType::kApproach, found, "close the last metres");
    approach.distance_m = config_.approach_distance_m;
    out.push_back(approach);
    out.push_back(Make(SubgoalType::kVerify, found, "confirm the target up close"));
  }
  return out;
}

Decomposition TaskDecomposer::WithModelAnswer(Decomposition rules,
                                              std::string_view model_json) const {
  absl::StatusOr<std::vector<Subgoal>> model = ParseModelSubgoals(model_json);
  if (!model.ok()) {
    rules.rejection = absl::StrCat("model answer rejected: ", model.status().message());
    return rules;
  }
  Decomposition result;
  result.subgoals = *std::move(model);
  result.complex = rules.complex;
  result.source = "model";
  return result;
}

}  // namespace semnav::reasoning
