// Subgoal vocabulary of the task decomposer (seed 002, 3.2.1).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace semnav::reasoning {

enum class SubgoalType {
  kNavigate,
  kFind,
  kApproach,
  kVerify,
  kLookAround,
  kExplore,
  kBacktrack,
  kWait
};

// "NAVIGATE", "FIND", ... as used in model JSON and the operator API.
std::string_view SubgoalTypeName(SubgoalType type);
std::optional<SubgoalType> ParseSubgoalType(std::string_view name);
// NAVIGATE, FIND, APPROACH and VERIFY act on a named target; the others need none.
bool RequiresTarget(SubgoalType type);

// What the user wants to reach, in canonical (English) lexicon names.
struct TargetSpec {
  std::string name;  // object or room, e.g. "cup", "kitchen"; empty: none.
  bool is_room = false;
  std::vector<std::string> colours;  // e.g. {"red"}.
  std::string relation;              // "near", "left_of", ...; empty: no spatial hint.
  std::string anchor;                // object the relation refers to, e.g. "door"; may be empty.
  std::string text;                  // the words as the user wrote them, for prompts and display.

  bool empty() const { return name.empty(); }
  bool operator==(const TargetSpec&) const = default;
};

struct Subgoal {
  SubgoalType type = SubgoalType::kExplore;
  TargetSpec target;
  double distance_m = 0.0;  // APPROACH: stop this far from the target.
  double duration_s = 0.0;  // WAIT / LOOK_AROUND: how long; 0 = executor default.
  std::string reason;       // why this step exists, shown to the operator.

  bool operator==(const Subgoal&) const = default;
};

// The first object target of a subgoal list (rooms skipped), else the first room; nullptr if none.
const TargetSpec* PrimaryTarget(const std::vector<Subgoal>& subgoals);

// "NAVIGATE(kitchen) FIND(red cup) ..." for logs and test failure messages.
std::string DescribeSubgoals(const std::vector<Subgoal>& subgoals);

}  // namespace semnav::reasoning
