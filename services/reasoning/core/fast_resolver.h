// Fast path of goal resolution (seed 002, 3.2.2, System 1): fuse four scores per scene-graph
// object and accept the best one without any model call when it exceeds the threshold.
//   fused = 0.35 label_match + 0.35 embedding_similarity + 0.15 detector + 0.15 spatial_hint,
// over the terms that apply (no embeddings: no embedding term; no relation asked: no spatial
// term), divided by the sum of their weights.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include "services/reasoning/core/label_matcher.h"
#include "services/reasoning/core/scene_graph.h"
#include "services/reasoning/core/subgoal.h"

namespace semnav::reasoning {

struct FastResolverConfig {
  double label_weight = 0.35;
  double embedding_weight = 0.35;
  double detector_weight = 0.15;
  double spatial_weight = 0.15;
  double fast_threshold = 0.75;         // fused > this -> goal without a model call.
  int detection_count_saturation = 10;  // detector term = score * min(1, count / this).
  double unknown_colour_factor = 0.5;   // label match when a colour is asked but not reported.
};

struct ScoredObject {
  int64_t object_id = 0;
  double label = 0.0;      // [0, 1]
  double embedding = 0.0;  // [0, 1]: max(0, cosine); 0 without embeddings (left out of fused).
  double detector = 0.0;   // [0, 1]
  double spatial = 0.0;    // 1 when the asked relation to the anchor is in the graph, else 0
                           // (no relation asked: left out of fused).
  double fused = 0.0;
};

struct FastResolution {
  std::optional<ScoredObject> best;  // highest fused score among objects with a label match.
  bool accepted = false;             // best->fused > fast_threshold.
};

class FastResolver {
 public:
  FastResolver(const Lexicon* lexicon, FastResolverConfig config);

  // `text_embedding` is the target's text embedding from the model proxy, or empty. Objects in
  // `excluded` (rejected by the operator or by verification) are skipped.
  FastResolution Resolve(const TargetSpec& target, const SceneGraph& graph,
                         const std::vector<float>& text_embedding,
                         const std::set<int64_t>& excluded) const;
  // The four terms and their fusion for one object. Objects without any label match score 0
  // everywhere: even a perfect embedding, detector and spatial term (0.65) cannot pass 0.75.
  ScoredObject Score(const TargetSpec& target, const SceneObject& object, const SceneGraph& graph,
                     const std::vector<float>& text_embedding) const;

  const FastResolverConfig& config() const { return config_; }
  const LabelMatcher& matcher() const { return matcher_; }

 private:
  ScoredObject ScorePrepared(const TargetSpec& target, const PreparedTarget& prepared,
                             const SceneObject& object, const SceneGraph& graph,
                             const std::vector<float>& text_embedding) const;
  double SpatialHint(const TargetSpec& target, const SceneObject& object,
                     const SceneGraph& graph) const;
  LabelMatcher matcher_;
  FastResolverConfig config_;
};

// Cosine similarity of two equal-length vectors; 0 if either is empty, zero or the sizes differ.
double Cosine(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace semnav::reasoning
