// ESCA selective grounding (seed 002, 3.2.2 slow path): shrink the scene graph before a model call
// by keyword match -> 1-hop relation expansion -> region expansion (about 200 -> 15 objects).
#pragma once

#include <cstdint>
#include <vector>

#include "services/reasoning/core/label_matcher.h"
#include "services/reasoning/core/scene_graph.h"
#include "services/reasoning/core/subgoal.h"

namespace semnav::reasoning {

struct GroundingConfig {
  int max_objects = 15;
};

struct GroundedGraph {
  SceneGraph graph;                   // selected objects, relations among them, their regions.
  std::vector<int64_t> keyword_hits;  // objects matched by the target or anchor name.
  bool open_vocabulary = false;       // one object per class: no label can name the target.
};

// Keyword hits are objects whose name overlaps the target's or the anchor's (colour ignored, so
// the model can still pick "the red one" among cups), best match first; then the other ends of
// relations touching them, nearest relation first; then objects of the same regions (or of a region
// named like the target room), nearest to the first hit first; stopping at `max_objects`. A target
// the lexicon has no object for and no label names (open vocabulary) grounds one object per
// label seen instead, most-detected first, so the model can say which class it is.
GroundedGraph SelectiveGrounding(const TargetSpec& target, const SceneGraph& graph,
                                 const LabelMatcher& matcher, const GroundingConfig& config);

}  // namespace semnav::reasoning
