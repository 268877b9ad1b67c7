// Label match of the fast path (seed 002, 3.2.2): compares a target with a detector label through
// the bilingual lexicon, so "沙发", "sofa" and "couch" are the same object, and checks colours.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "services/common/lexicon/lexicon.h"
#include "services/reasoning/core/scene_graph.h"
#include "services/reasoning/core/subgoal.h"

namespace semnav::reasoning {

// A detector label split into its canonical object name and the colours it mentions.
struct NormalisedLabel {
  std::string name;                  // canonical, e.g. "couch"
  std::vector<std::string> colours;  // canonical, e.g. {"red"}
};

// A target in canonical form, prepared once per query rather than once per object.
struct PreparedTarget {
  std::string name;                  // canonical name
  std::vector<std::string> words;    // distinct words of name
  std::vector<std::string> colours;  // canonical colours
};

class LabelMatcher {
 public:
  // `lexicon` must outlive the matcher. `unknown_colour_factor` scales the match when the target
  // asks for a colour the object does not report.
  LabelMatcher(const Lexicon* lexicon, double unknown_colour_factor);

  NormalisedLabel Normalise(std::string_view label,
                            const std::vector<std::string>& attributes) const;
  PreparedTarget Prepare(const TargetSpec& target) const;
  // 1 for the same canonical name, else the Jaccard overlap of their words ("cup" vs
  // "coffee cup" = 0.5), times the colour factor: 1 if every asked colour is reported, 0 if the
  // object reports other colours only, `unknown_colour_factor` if it reports none.
  double Match(const PreparedTarget& target, const NormalisedLabel& object) const;
  double Match(const TargetSpec& target, const NormalisedLabel& object) const {
    return Match(Prepare(target), object);
  }
  // Canonical name equality only (for relation anchors and region names).
  bool SameName(std::string_view a, std::string_view b) const;

  const Lexicon& lexicon() const { return *lexicon_; }

 private:
  const Lexicon* lexicon_;
  double unknown_colour_factor_;
};

}  // namespace semnav::reasoning
