#include "services/reasoning/core/subgoal.h"

#include <array>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace semnav::reasoning {
namespace {

constexpr std::array<std::pair<SubgoalType, std::string_view>, 8> kNames = {{
    {SubgoalType::kNavigate, "NAVIGATE"},
    {SubgoalType::kFind, "FIND"},
    {SubgoalType::kApproach, "APPROACH"},
    {SubgoalType::kVerify, "VERIFY"},
    {SubgoalType::kLookAround, "LOOK_AROUND"},
    {SubgoalType::kExplore, "EXPLORE"},
    {SubgoalType::kBacktrack, "BACKTRACK"},
    {SubgoalType::kWait, "WAIT"},
}};

}  // namespace

std::string_view SubgoalTypeName(SubgoalType type) {
  for (const auto& [value, name] : kNames) {
    if (value == type) return name;
  }
  return "UNKNOWN";
}

std::optional<SubgoalType> ParseSubgoalType(std::string_view name) {
  for (const auto& [value, known] : kNames) {
    if (known == name) return value;
  }
  return std::nullopt;
}

bool RequiresTarget(SubgoalType type) {
  return type == SubgoalType::kNavigate || type == SubgoalType::kFind ||
         type == SubgoalType::kApproach || type == SubgoalType::kVerify;
}

const TargetSpec* PrimaryTarget(const std::vector<Subgoal>& subgoals) {
  const TargetSpec* room = nullptr;
  for (const Subgoal& goal : subgoals) {
    if (goal.target.empty()) continue;
    if (!goal.target.is_room) return &goal.target;
    if (room == nullptr) room = &goal.target;
  }
  return room;
}

std::string DescribeSubgoals(const std::vector<Subgoal>& subgoals) {
  return absl::StrJoin(subgoals, " ", [](std::string* out, const Subgoal& goal) {
    std::string target = absl::StrJoin(goal.target.colours, " ");
    if (!goal.target.name.empty())
      absl::StrAppend(&target, target.empty() ? "" : " ", goal.target.name);
    if (!goal.target.relation.empty()) {
      absl::StrAppend(&target, " ", goal.target.relation, " ", goal.target.anchor);
    }
    absl::StrAppend(out, std::string(SubgoalTypeName(goal.type)), "(", target, ")");
  });
}

}  // namespace semnav::reasoning
