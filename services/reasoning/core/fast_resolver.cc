#include "services/reasoning/core/fast_resolver.h"

#include <algorithm>
#include <cmath>

namespace semnav::reasoning {
namespace {

// The graph stores each relation once; these read it back from the other side.
std::string Inverse(const std::string& relation) {
  if (relation == "near") return "near";
  if (relation == "left_of") return "right_of";
  if (relation == "right_of") return "left_of";
  if (relation == "in_front_of") return "behind";
  if (relation == "behind") return "in_front_of";
  return "";
}

}  // namespace

double Cosine(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.empty() || a.size() != b.size()) return 0.0;
  double dot = 0.0, na = 0.0, nb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    dot += static_cast<double>(a[i]) * b[i];
    na += static_cast<double>(a[i]) * a[i];
    nb += static_cast<double>(b[i]) * b[i];
  }
  if (na == 0.0 || nb == 0.0) return 0.0;
  return dot / std::sqrt(na * nb);
}

FastResolver::FastResolver(const Lexicon* lexicon, FastResolverConfig config)
    : matcher_(lexicon, config.unknown_colour_factor), config_(config) {}

double FastResolver::SpatialHint(const TargetSpec& target, const SceneObject& object,
                                 const SceneGraph& graph) const {
  if (target.relation.empty() || target.anchor.empty()) return 0.0;
  const std::string inverse = Inverse(target.relation);
  for (const SceneRelation& relation : graph.relations) {
    int64_t other = -1;
    if (relation.subject_id == object.id && relation.relation == target.relation) {
      other = relation.object_id;
    } else if (relation.object_id == object.id && !inverse.empty() &&
               relation.relation == inverse) {
      other = relation.subject_id;
    }
    if (other < 0) continue;
    const SceneObject* anchor = graph.FindObject(other);
    if (anchor != nullptr &&
        matcher_.SameName(matcher_.Normalise(anchor->label, {}).name, target.anchor)) {
      return 1.0;
    }
  }
  return 0.0;
}

ScoredObject FastResolver::Score(const TargetSpec& target, const SceneObject& object,
                                 const SceneGraph& graph,
                                 const std::vector<float>& text_embedding) const {
  return ScorePrepared(target, matcher_.Prepare(target), object, graph, text_embedding);
}

ScoredObject FastResolver::ScorePrepared(const TargetSpec& target, const PreparedTarget& prepared,
                                         const SceneObject& object, const SceneGraph& graph,
                                         const std::vector<float>& text_embedding) const {
  ScoredObject scored;
  scored.object_id = object.id;
  scored.label = matcher_.Match(prepared, matcher_.Normalise(object.label, object.attributes));
  if (scored.label <= 0.0) return scored;
  // A term that cannot speak for this target is left out and the other weights renormalised:
  // without a text and an object embedding there is no CLIP term (the seed's stand-in, the label
  // match counted twice, let one glimpse of a label pass on label alone), and a target that
  // names no relation has no spatial hint to hit (with it fixed at 0, the seed's weights cap an
  // exact match below 0.85 and the slow path was asked for nearly every target, issue 15).
  const bool have_embeddings =
      !text_embedding.empty() && object.embedding.size() == text_embedding.size();
  const bool relation_asked = !target.relation.empty() && !target.anchor.empty();
  scored.embedding =
      have_embeddings ? std::max(0.0, Cosine(text_embedding, object.embedding)) : 0.0;
  const double count_factor = std::min(
      1.0, static_cast<double>(object.detection_count) / config_.detection_count_saturation);
  scored.detector = std::clamp(object.score, 0.0, 1.0) * count_factor;
  scored.spatial = SpatialHint(target, object, graph);
  const double embedding_weight = have_embeddings ? config_.embedding_weight : 0.0;
  const double spatial_weight = relation_asked ? config_.spatial_weight : 0.0;
  const double weights =
      config_.label_weight + embedding_weight + config_.detector_weight + spatial_weight;
  scored.fused =
      weights <= 0.0
          ? 0.0
          : (config_.label_weight * scored.label + embedding_weight * scored.embedding +
             config_.detector_weight * scored.detector + spatial_weight * scored.spatial) /
                weights;
  return scored;
}

FastResolution FastResolver::Resolve(const TargetSpec& target, const SceneGraph& graph,
                                     const std::vector<float>& text_embedding,
                                     const std::set<int64_t>& excluded) const {
  FastResolution resolution;
  const PreparedTarget prepared = matcher_.Prepare(target);
  for (const SceneObject& object : graph.objects) {
    if (excluded.count(object.id) > 0) continue;
    ScoredObject scored = ScorePrepared(target, prepared, object, graph, text_embedding);
    if (scored.label <= 0.0) continue;
    if (!resolution.best.has_value() || scored.fused > resolution.best->fused)
      resolution.best = scored;
  }
  resolution.accepted =
      resolution.best.has_value() && resolution.best->fused > config_.fast_threshold;
  return resolution;
}

}  // namespace semnav::reasoning
