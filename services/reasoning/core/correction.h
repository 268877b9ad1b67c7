// Multi-turn correction (seed 002, 11.3 open item): "不是这个，是那个红色的" / "not that one, the
// red one" refines the active task's target instead of starting a new task.
#pragma once

#include <optional>

#include "services/reasoning/core/instruction_parser.h"
#include "services/reasoning/core/subgoal.h"

namespace semnav::reasoning {

struct Correction {
  TargetSpec target;             // the active target with the corrected name/colours/relation.
  bool exclude_current = false;  // the user rejected the object currently pursued.
};

// A correction has no action word and negates ("not", "不是"), points ("that one", "那个") or
// names only new attributes. Returns nullopt for anything else (a new instruction).
std::optional<Correction> ReadCorrection(const ParsedInstruction& parsed, const TargetSpec& active);

}  // namespace semnav::reasoning
