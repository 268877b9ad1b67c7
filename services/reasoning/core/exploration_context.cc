#include "services/reasoning/core/exploration_context.h"

#include <string>

namespace semnav::reasoning {

double CooccurrencePrior::RoomCooccurrence(std::string_view target,
                                           const std::vector<std::string>& labels) const {
  if (labels.empty()) return 0.0;
  double sum = 0.0;
  for (const std::string& label : labels) sum += Cooccurrence(target, label);
  return sum / static_cast<double>(labels.size());
}

ExplorationContext BuildExplorationContext(const TargetSpec& target, const SceneGraph& graph,
                                           const LabelMatcher& matcher,
                                           const CooccurrencePrior* prior,
                                           const TopologicalMemory* memory) {
  ExplorationContext context;
  if (memory != nullptr) {
    for (const TopoNode& node : memory->nodes()) context.visited.push_back(node.position);
  }
  if (target.empty() || target.is_room) return context;
  const PreparedTarget prepared = matcher.Prepare(target);
  for (const SceneObject& object : graph.objects) {
    const NormalisedLabel label = matcher.Normalise(object.label, object.attributes);
    ExplorationHint hint{object.label, object.position, matcher.Match(prepared, label), 0.0, 0.0};
    if (!target.anchor.empty() && matcher.SameName(label.name, target.anchor)) hint.relation = 1.0;
    if (prior != nullptr && label.name != prepared.name)
      hint.cooccurrence = prior->Cooccurrence(prepared.name, label.name);
    if (hint.relevance > 0.0 || hint.relation > 0.0 || hint.cooccurrence > 0.0)
      context.objects.push_back(hint);
  }
  if (prior == nullptr) return context;
  // Rooms: the objects of a scene region (mapping's 3 m clusters) seen together say more about
  // where the target is than any one of them. The target's own kind is left out (a seen target
  // is approached, not explored for).
  for (const SceneRegion& region : graph.regions) {
    std::vector<std::string> labels;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int64_t id : region.object_ids) {
      const SceneObject* object = graph.FindObject(id);
      if (object == nullptr) continue;
      const NormalisedLabel label = matcher.Normalise(object->label, object->attributes);
      if (label.name == prepared.name) continue;
      labels.push_back(label.name);
      centre += object->position;
    }
    if (labels.size() < 2) continue;
    centre /= static_cast<double>(labels.size());
    const double room = prior->RoomCooccurrence(prepared.name, labels);
    if (room > 0.0)
      context.objects.push_back({"region:" + std::to_string(region.id), centre, 0.0, 0.0, room});
  }
  return context;
}

}  // namespace semnav::reasoning
