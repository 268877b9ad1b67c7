// Local copy of mapping's scene graph kept from WatchSceneGraph: a snapshot, then deltas (removed
// ids first, then upserts; relations and regions replace the copy), in the gateway's core values.
#pragma once

#include <cstdint>
#include <map>

#include "semnav/mapping/v1/mapping_service.pb.h"
#include "services/reasoning/core/scene_graph.h"

namespace semnav::reasoning {

class SceneGraphMirror {
 public:
  // False when a delta does not continue the mirrored revision (the watch must restart from a
  // snapshot); the mirror is then unchanged.
  bool Apply(const mapping::v1::WatchSceneGraphResponse& update);
  uint64_t revision() const { return graph_.revision; }
  const SceneGraph& graph() const { return graph_; }

 private:
  void SetRelationsAndRegions(
      const google::protobuf::RepeatedPtrField<mapping::v1::Relation>& relations,
      const google::protobuf::RepeatedPtrField<mapping::v1::Region>& regions);
  void Rebuild(uint64_t revision);

  std::map<uint64_t, SceneObject> objects_;
  SceneGraph graph_;
};

}  // namespace semnav::reasoning
