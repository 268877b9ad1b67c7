// Task decomposition (seed 002, 3.2.1): rules first for simple instructions, the model for
// complex ones; model subgoals are validated and the rules are used when they are rejected.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "services/reasoning/core/instruction_parser.h"
#include "services/reasoning/core/subgoal.h"

namespace semnav::reasoning {

struct DecomposerConfig {
  double approach_distance_m = 0.5;  // LOVON approach primitive stops 0.5 m from the target.
  int max_simple_unknown_words = 2;  // more unknown words than this -> ask the model.
};

struct Decomposition {
  std::vector<Subgoal> subgoals;  // rule result, always usable offline.
  bool complex = false;           // the rules recommend the model path (several clauses/targets
                                  // or words the lexicon does not know).
  std::string source = "rules";   // "rules" or "model".
  std::string rejection;          // why the model's answer was not used; empty otherwise.
};

class TaskDecomposer {
 public:
  TaskDecomposer(InstructionParser parser, DecomposerConfig config);

  Decomposition Decompose(std::string_view instruction);
  // Subgoals for an already parsed clause list (used by correction and tests).
  std::vector<Subgoal> FromClauses(const std::vector<Clause>& clauses) const;
  // Prefers `model_json` when it validates (see subgoal_json.h), else keeps the rule result and
  // says why in `rejection`.
  Decomposition WithModelAnswer(Decomposition rules, std::string_view model_json) const;

  // Each FIND of an object that no later APPROACH or VERIFY of the same target follows gets
  // them, as the rules read "find X" (seed 002: FIND ... APPROACH VERIFY): the robot goes to what
  // it found. For model plans of instructions the rules could not read at all.
  std::vector<Subgoal> CompleteFinds(std::vector<Subgoal> subgoals) const;

  InstructionParser& parser() { return parser_; }

 private:
  std::vector<Subgoal> FromClause(const Clause& clause) const;
  InstructionParser parser_;
  DecomposerConfig config_;
};

}  // namespace semnav::reasoning
