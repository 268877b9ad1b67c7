#include "services/reasoning/core/scene_graph.h"

namespace semnav::reasoning {

const SceneObject* SceneGraph::FindObject(int64_t id) const {
  for (const SceneObject& object : objects) {
    if (object.id == id) return &object;
  }
  return nullptr;
}

std::shared_ptr<const SceneGraph> EmptySceneGraph() {
  static const auto* const empty =
      new std::shared_ptr<const SceneGraph>(std::make_shared<const SceneGraph>());
  return *empty;
}

}  // namespace semnav::reasoning
