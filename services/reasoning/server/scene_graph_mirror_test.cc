#include "services/reasoning/server/scene_graph_mirror.h"

#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

namespace mapping_api = ::semnav::mapping::v1;

mapping_api::SceneObject Object(uint64_t id, const char* label, double x, uint32_t observations) {
  mapping_api::SceneObject object;
  object.set_id(id);
  object.set_label(label);
  object.mutable_position()->set_x(x);
  object.set_score(0.9);
  object.set_observation_count(observations);
  object.set_region_id(0);
  return object;
}

TEST(GatewaySceneGraphMirrorTest, SnapshotThenDeltasThenGap) {
  SceneGraphMirror mirror;
  mapping_api::WatchSceneGraphResponse snapshot;
  snapshot.mutable_snapshot()->set_revision(4);
  *snapshot.mutable_snapshot()->add_objects() = Object(1, "door", 1.0, 3);
  *snapshot.mutable_snapshot()->add_objects() = Object(2, "chair", 2.0, 5);
  ASSERT_TRUE(mirror.Apply(snapshot));
  EXPECT_EQ(mirror.revision(), 4u);
  ASSERT_EQ(mirror.graph().objects.size(), 2u);

  mapping_api::WatchSceneGraphResponse delta;
  delta.mutable_delta()->set_from_revision(4);
  delta.mutable_delta()->set_revision(6);
  delta.mutable_delta()->add_removed_object_ids(2);
  *delta.mutable_delta()->add_upserted_objects() = Object(1, "door", 1.5, 4);
  delta.mutable_delta()->mutable_upserted_objects(0)->set_miss_count(7);
  *delta.mutable_delta()->add_upserted_objects() = Object(3, "fire extinguisher", 1.8, 1);
  mapping_api::Relation* relation = delta.mutable_delta()->add_relations();
  relation->set_subject_id(3);
  relation->set_kind(mapping_api::RELATION_KIND_NEAR);
  relation->set_object_id(1);
  relation->set_distance(0.3);
  mapping_api::Region* region = delta.mutable_delta()->add_regions();
  region->set_name("corridor");
  region->add_object_ids(1);
  region->add_object_ids(3);
  ASSERT_TRUE(mirror.Apply(delta));
  const SceneGraph& graph = mirror.graph();
  EXPECT_EQ(graph.revision, 6u);
  ASSERT_EQ(graph.objects.size(), 2u);
  EXPECT_DOUBLE_EQ(graph.FindObject(1)->position.x(), 1.5);
  EXPECT_EQ(graph.FindObject(1)->detection_count, 4);
  EXPECT_EQ(graph.FindObject(1)->miss_count, 7);  // VERIFY's evidence against it
  EXPECT_EQ(graph.FindObject(2), nullptr);
  ASSERT_EQ(graph.relations.size(), 1u);
  EXPECT_EQ(graph.relations[0].relation, "near");
  EXPECT_EQ(graph.regions[0].object_ids, (std::vector<int64_t>{1, 3}));

  delta.mutable_delta()->set_from_revision(9);  // not the mirrored revision: a gap
  delta.mutable_delta()->set_revision(10);
  EXPECT_FALSE(mirror.Apply(delta));
  EXPECT_EQ(mirror.revision(), 6u);
}

}  // namespace
}  // namespace semnav::reasoning
