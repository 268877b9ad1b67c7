#include "services/reasoning/core/selective_grounding.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

namespace semnav::reasoning {
namespace {

class Selection {
 public:
  explicit Selection(std::size_t limit) : limit_(limit) {}
  bool full() const { return ids_.size() >= limit_; }
  bool Add(int64_t id) {
    if (full() || !set_.insert(id).second) return false;
    ids_.push_back(id);
    return true;
  }
  bool Has(int64_t id) const { return set_.count(id) > 0; }
  const std::vector<int64_t>& ids() const { return ids_; }

 private:
  std::size_t limit_;
  std::vector<int64_t> ids_;
  std::set<int64_t> set_;
};

}  // namespace

GroundedGraph SelectiveGrounding(const TargetSpec& target, const SceneGraph& graph,
                                 const LabelMatcher& matcher, const GroundingConfig& config) {
  GroundedGraph out;
  Selection selection(static_cast<std::size_t>(std::max(0, config.max_objects)));
  std::unordered_map<int64_t, const SceneObject*> by_id;
  for (const SceneObject& object : graph.objects) by_id[object.id] = &object;

  // 1. Keyword match on the target and the anchor names.
  TargetSpec name_only;
  name_only.name = target.name;
  TargetSpec anchor_spec;
  anchor_spec.name = target.anchor;
  const PreparedTarget wanted = matcher.Prepare(name_only);
  const PreparedTarget anchor = matcher.Prepare(anchor_spec);
  std::vector<std::pair<double, const SceneObject*>> hits;
  for (const SceneObject& object : graph.objects) {
    const NormalisedLabel label = matcher.Normalise(object.label, object.attributes);
    double match = matcher.Match(wanted, label);
    if (!target.anchor.empty()) match = std::max(match, 0.5 * matcher.Match(anchor, label));
    if (match > 0.0) hits.push_back({match + 1e-3 * object.score, &object});
  }
  std::stable_sort(hits.begin(), hits.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [match, object] : hits) {
    if (selection.Add(object->id)) out.keyword_hits.push_back(object->id);
  }

  // 1b. Open vocabulary (issue 15): a target the lexicon has no object for ("复印机", "coffee
  // machine") matches no label by name, so the model judges the classes seen instead: one
  // candidate per label (its most-detected instance), most-detected labels first.
  if (out.keyword_hits.empty() && !target.is_room && !target.name.empty() &&
      matcher.lexicon().Find(target.name, TermKind::kObject) == nullptr) {
    std::map<std::string, const SceneObject*> per_label;
    for (const SceneObject& object : graph.objects) {
      const SceneObject*& best = per_label[matcher.Normalise(object.label, {}).name];
      if (best == nullptr || object.detection_count > best->detection_count) best = &object;
    }
    std::vector<const SceneObject*> classes;
    for (const auto& [label, object] : per_label) classes.push_back(object);
    std::stable_sort(classes.begin(), classes.end(),
                     [](const SceneObject* a, const SceneObject* b) {
                       return a->detection_count > b->detection_count;
                     });
    for (const SceneObject* object : classes) selection.Add(object->id);
    out.open_vocabulary = !classes.empty();
  }

  // 2. One-hop relation expansion, nearest relation first.
  std::vector<const SceneRelation*> touching;
  for (const SceneRelation& relation : graph.relations) {
    if (selection.Has(relation.subject_id) != selection.Has(relation.object_id))
      touching.push_back(&relation);
  }
  std::stable_sort(
      touching.begin(), touching.end(),
      [](const SceneRelation* a, const SceneRelation* b) { return a->distance_m < b->distance_m; });
  for (const SceneRelation* relation : touching) {
    selection.Add(selection.Has(relation->subject_id) ? relation->object_id : relation->subject_id);
  }

  // 3. Region expansion around the first hit (or inside a region named like the target room).
  std::set<int64_t> regions;
  for (int64_t id : out.keyword_hits) {
    if (by_id.at(id)->region_id >= 0) regions.insert(by_id.at(id)->region_id);
  }
  for (const SceneRegion& region : graph.regions) {
    if (target.is_room && matcher.SameName(region.name, target.name)) regions.insert(region.id);
  }
  const Eigen::Vector3d centre = out.keyword_hits.empty()
                                     ? Eigen::Vector3d::Zero()
                                     : by_id.at(out.keyword_hits.front())->position;
  std::vector<std::pair<double, int64_t>> region_members;
  for (const SceneRegion& region : graph.regions) {
    if (regions.count(region.id) == 0) continue;
    for (int64_t id : region.object_ids) {
      auto it = by_id.find(id);
      if (it != by_id.end()) region_members.push_back({(it->second->position - centre).norm(), id});
    }
  }
  std::stable_sort(region_members.begin(), region_members.end());
  for (const auto& [distance, id] : region_members) selection.Add(id);

  // Assemble the subgraph in the original object order.
  for (const SceneObject& object : graph.objects) {
    if (selection.Has(object.id)) out.graph.objects.push_back(object);
  }
  for (const SceneRelation& relation : graph.relations) {
    if (selection.Has(relation.subject_id) && selection.Has(relation.object_id)) {
      out.graph.relations.push_back(relation);
    }
  }
  for (const SceneRegion& region : graph.regions) {
    SceneRegion kept{region.id, region.name, {}};
    for (int64_t id : region.object_ids) {
      if (selection.Has(id)) kept.object_ids.push_back(id);
    }
    if (!kept.object_ids.empty()) out.graph.regions.push_back(std::move(kept));
  }
  out.graph.revision = graph.revision;
  return out;
}

}  // namespace semnav::reasoning
