#include "services/reasoning/core/selective_grounding.h"

#include <algorithm>

#include "gtest/gtest.h"
#include "services/reasoning/core/scene_graph_json.h"
#include "services/reasoning/testing/synthetic_scene.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

bool Contains(const SceneGraph& graph, int64_t id) { return graph.FindObject(id) != nullptr; }

TEST(GatewayGroundingTest, TwoHundredObjectsShrinkToFifteenKeepingTheTarget) {
  const SceneGraph scene = testing::SyntheticScene(18, 11);
  ASSERT_EQ(scene.objects.size(), 200u);
  LabelMatcher matcher(&ShippedLexicon(), 0.5);
  TargetSpec target;
  target.name = "灭火器";
  GroundedGraph grounded = SelectiveGrounding(target, scene, matcher, GroundingConfig{});
  // Keyword hit + its door (1-hop) + the other 11 objects of region 9 = 13 <= 15.
  EXPECT_EQ(grounded.graph.objects.size(), 13u);
  EXPECT_EQ(grounded.keyword_hits, std::vector<int64_t>{testing::kSyntheticTargetId});
  EXPECT_TRUE(Contains(grounded.graph, testing::kSyntheticTargetId));
  EXPECT_TRUE(Contains(grounded.graph, testing::kSyntheticDoorId));
  for (const SceneObject& object : grounded.graph.objects)
    EXPECT_EQ(object.region_id, 9) << object.id;
  const double reduction =
      1.0 - static_cast<double>(EstimateTokens(SceneGraphToPromptJson(grounded.graph))) /
                EstimateTokens(SceneGraphToPromptJson(scene));
  EXPECT_GE(reduction, 0.9);
}

TEST(GatewayGroundingTest, OrderIsKeywordThenRelationThenRegion) {
  SceneGraph scene;
  auto add = [&](int64_t id, const char* label, int64_t region, double x) {
    SceneObject object;
    object.id = id;
    object.label = label;
    object.region_id = region;
    object.position = Eigen::Vector3d(x, 0, 0);
    scene.objects.push_back(object);
  };
  add(1, "cup", 0, 0.0);
  add(2, "dining table", 1, 0.5);  // related to the cup, other region
  add(3, "chair", 0, 3.0);         // same region, far
  add(4, "sink", 0, 1.0);          // same region, near
  add(5, "bed", 2, 9.0);           // unrelated
  scene.relations = {{1, "on", 2, 0.4}};
  scene.regions = {{0, "kitchen", {1, 3, 4}}, {1, "dining", {2}}, {2, "bedroom", {5}}};
  LabelMatcher matcher(&ShippedLexicon(), 0.5);
  TargetSpec target;
  target.name = "cup";
  GroundingConfig config;
  config.max_objects = 3;
  GroundedGraph grounded = SelectiveGrounding(target, scene, matcher, config);
  std::vector<int64_t> ids;
  for (const SceneObject& object : grounded.graph.objects) ids.push_back(object.id);
  EXPECT_EQ(ids, (std::vector<int64_t>{1, 2, 4}));
  ASSERT_EQ(grounded.graph.relations.size(), 1u);
  ASSERT_EQ(grounded.graph.regions.size(), 2u);
  EXPECT_EQ(grounded.graph.regions[0].object_ids, (std::vector<int64_t>{1, 4}));
}

TEST(GatewayGroundingTest, NoKeywordHitLeavesOnlyTheRoomRegion) {
  SceneGraph scene = testing::SyntheticScene(3, 4);
  scene.regions[1].name = "kitchen";
  LabelMatcher matcher(&ShippedLexicon(), 0.5);
  TargetSpec target;
  target.name = "厨房";
  target.is_room = true;
  GroundedGraph grounded = SelectiveGrounding(target, scene, matcher, GroundingConfig{});
  EXPECT_TRUE(grounded.keyword_hits.empty());
  // Region 1 holds its 4 objects plus the synthetic target and door.
  EXPECT_EQ(grounded.graph.objects.size(), 6u);
}

SceneObject Seen(int64_t id, const char* label, int detections) {
  SceneObject object;
  object.id = id;
  object.label = label;
  object.score = 0.8;
  object.detection_count = detections;
  return object;
}

// Open vocabulary (issue 15): no label can name "复印机", which the lexicon does not know, so the
// model is shown one object per class seen (the most-detected of each), most-detected first. A
// target the lexicon knows but nobody has seen yet grounds nothing (no call until it is seen).
TEST(GatewayGroundingTest, OpenVocabularyTargetGroundsOneObjectPerClass) {
  SceneGraph scene;
  scene.objects = {Seen(1, "chair", 3), Seen(2, "chair", 9), Seen(3, "printer", 2),
                   Seen(4, "desk", 5), Seen(5, "chair", 1)};
  LabelMatcher matcher(&ShippedLexicon(), 0.5);
  TargetSpec copier;
  copier.name = "复印机";
  GroundingConfig config;
  GroundedGraph grounded = SelectiveGrounding(copier, scene, matcher, config);
  EXPECT_TRUE(grounded.keyword_hits.empty());
  std::vector<int64_t> ids;
  for (const SceneObject& object : grounded.graph.objects) ids.push_back(object.id);
  EXPECT_EQ(ids, (std::vector<int64_t>{2, 3, 4}));  // chair 2 (9 detections), printer, desk
  config.max_objects = 2;
  EXPECT_EQ(SelectiveGrounding(copier, scene, matcher, config).graph.objects.size(), 2u);
  TargetSpec known;
  known.name = "backpack";
  EXPECT_TRUE(SelectiveGrounding(known, scene, matcher, GroundingConfig{}).graph.objects.empty());
}

}  // namespace
}  // namespace semnav::reasoning
