#include "services/reasoning/core/scene_graph.h"

namespace semnav::reasoning {

const SceneObject* SceneGraph::FindObject(int64_t id) const {
  for (const SceneObject& object : objects) {
    if (object.id == id) return &object;
  }
  return nullptr;
}

}  // namespace semnav::reasoning
