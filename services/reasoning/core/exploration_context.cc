#include "services/reasoning/core/exploration_context.h"

namespace semnav::reasoning {

ExplorationContext BuildExplorationContext(const TargetSpec& target, const SceneGraph& graph,
                                           const LabelMatcher& matcher, const CooccurrencePrior* prior,
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
    if (prior != nullptr && label.name != prepared.name) hint.cooccurrence = prior->Cooccurrence(prepared.name, label.name);
    if (hint.relevance > 0.0 || hint.relation > 0.0 || hint.cooccurrence > 0.0) context.objects.push_back(hint);
  }
  return context;
}

}  // namespace semnav::reasoning
