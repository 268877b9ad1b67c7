// Rule-based reading of an instruction into clauses of actions, a room and target objects with
// colours and a spatial relation. English puts the target before the relation ("the chair near the
// door"); Chinese puts the anchor first ("门旁边的椅子"), which the parser follows per phrase.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "services/common/lexicon/lexicon.h"
#include "services/reasoning/core/subgoal.h"
#include "services/reasoning/core/text_segmenter.h"

namespace semnav::reasoning {

struct Clause {
  std::vector<std::string> actions;        // canonical action names in order: "go", "find", ...
  TargetSpec room;                         // empty when no room is named.
  std::vector<TargetSpec> objects;         // targets (anchors live inside their target's spec).
  std::vector<std::string> loose_colours;  // colours not followed by an object ("the red one").
  bool negated = false;                    // "not", "不是".
  bool deictic = false;                    // "that one", "这个".
  int unknown_words = 0;                   // words outside the lexicon.
};

struct ParsedInstruction {
  std::vector<Clause> clauses;
  int unknown_words() const;
};

class InstructionParser {
 public:
  // `lexicon` must outlive the parser.
  explicit InstructionParser(const Lexicon* lexicon, TextSegmenter segmenter);
  ParsedInstruction Parse(std::string_view instruction);

 private:
  const Lexicon* lexicon_;
  TextSegmenter segmenter_;
};

}  // namespace semnav::reasoning
