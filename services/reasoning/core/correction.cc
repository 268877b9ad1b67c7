#include "services/reasoning/core/correction.h"

namespace semnav::reasoning {

std::optional<Correction> ReadCorrection(const ParsedInstruction& parsed,
                                         const TargetSpec& active) {
  bool negated = false;
  bool deictic = false;
  for (const Clause& clause : parsed.clauses) {
    if (!clause.actions.empty() || !clause.room.empty()) return std::nullopt;
    negated = negated || clause.negated;
    deictic = deictic || clause.deictic;
  }
  if (!negated && !deictic) return std::nullopt;
  Correction correction;
  correction.target = active;
  correction.exclude_current = negated;
  for (const Clause& clause : parsed.clauses) {
    if (!clause.loose_colours.empty()) correction.target.colours = clause.loose_colours;
    for (const TargetSpec& object : clause.objects) {
      correction.target.name = object.name;
      correction.target.text = object.text;
      if (!object.colours.empty()) correction.target.colours = object.colours;
      if (!object.relation.empty()) {
        correction.target.relation = object.relation;
        correction.target.anchor = object.anchor;
      }
    }
  }
  return correction;
}

}  // namespace semnav::reasoning
