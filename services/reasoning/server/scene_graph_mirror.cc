#include "services/reasoning/server/scene_graph_mirror.h"

#include <algorithm>

namespace semnav::reasoning {
namespace {

namespace mapping_api = ::semnav::mapping::v1;

const char* RelationName(mapping_api::RelationKind kind) {
  switch (kind) {
    case mapping_api::RELATION_KIND_NEAR:
      return "near";
    case mapping_api::RELATION_KIND_LEFT_OF:
      return "left_of";
    case mapping_api::RELATION_KIND_RIGHT_OF:
      return "right_of";
    case mapping_api::RELATION_KIND_IN_FRONT_OF:
      return "in_front_of";
    case mapping_api::RELATION_KIND_BEHIND:
      return "behind";
    case mapping_api::RELATION_KIND_ON:
      return "on";
    case mapping_api::RELATION_KIND_ABOVE:
      return "above";
    default:
      return "";
  }
}

SceneObject FromProto(const mapping_api::SceneObject& in) {
  SceneObject out;
  out.id = static_cast<int64_t>(in.id());
  out.label = in.label();
  out.position = Eigen::Vector3d(in.position().x(), in.position().y(), in.position().z());
  out.score = in.score();
  out.detection_count = static_cast<int>(in.observation_count());
  out.miss_count = static_cast<int>(std::min<uint32_t>(in.miss_count(), 1u << 30));
  out.region_id = in.region_id();
  out.embedding.assign(in.embedding().begin(), in.embedding().end());
  out.size = Eigen::Vector3d(in.size().x(), in.size().y(), in.size().z()).cwiseMax(0.0);
  return out;
}

}  // namespace

void SceneGraphMirror::SetRelationsAndRegions(
    const google::protobuf::RepeatedPtrField<mapping_api::Relation>& relations,
    const google::protobuf::RepeatedPtrField<mapping_api::Region>& regions) {
  graph_.relations.clear();
  for (const mapping_api::Relation& r : relations) {
    graph_.relations.push_back({static_cast<int64_t>(r.subject_id()), RelationName(r.kind()),
                                static_cast<int64_t>(r.object_id()), r.distance()});
  }
  graph_.regions.clear();
  for (const mapping_api::Region& r : regions) {
    SceneRegion region{r.id(), r.name(), {}};
    for (uint64_t id : r.object_ids()) region.object_ids.push_back(static_cast<int64_t>(id));
    graph_.regions.push_back(std::move(region));
  }
}

void SceneGraphMirror::Rebuild(uint64_t revision) {
  graph_.revision = revision;
  graph_.objects.clear();
  for (const auto& [id, object] : objects_) graph_.objects.push_back(object);
}

bool SceneGraphMirror::Apply(const mapping_api::WatchSceneGraphResponse& update) {
  if (update.has_snapshot()) {
    const mapping_api::SceneGraph& snapshot = update.snapshot();
    objects_.clear();
    for (const mapping_api::SceneObject& object : snapshot.objects())
      objects_[object.id()] = FromProto(object);
    SetRelationsAndRegions(snapshot.relations(), snapshot.regions());
    Rebuild(snapshot.revision());
    return true;
  }
  const mapping_api::SceneGraphDelta& delta = update.delta();
  if (delta.from_revision() != graph_.revision) return false;
  for (uint64_t id : delta.removed_object_ids()) objects_.erase(id);
  for (const mapping_api::SceneObject& object : delta.upserted_objects())
    objects_[object.id()] = FromProto(object);
  SetRelationsAndRegions(delta.relations(), delta.regions());
  Rebuild(delta.revision());
  return true;
}

}  // namespace semnav::reasoning
