#include "services/reasoning/core/fast_resolver.h"

#include "gtest/gtest.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

SceneObject Object(int64_t id, const char* label, double score, int count,
                   std::vector<std::string> attributes = {}) {
  SceneObject object;
  object.id = id;
  object.label = label;
  object.score = score;
  object.detection_count = count;
  object.attributes = std::move(attributes);
  return object;
}

TargetSpec Target(const char* name, std::vector<std::string> colours = {},
                  const char* relation = "", const char* anchor = "") {
  TargetSpec target;
  target.name = name;
  target.colours = std::move(colours);
  target.relation = relation;
  target.anchor = anchor;
  return target;
}

class GatewayFastResolverTest : public ::testing::Test {
 protected:
  FastResolver resolver_{&ShippedLexicon(), FastResolverConfig{}};
};

TEST_F(GatewayFastResolverTest, AllFourTermsByHand) {
  SceneGraph graph;
  graph.objects = {Object(1, "fire_extinguisher", 0.85, 15, {"red"}), Object(2, "door", 0.9, 20)};
  graph.relations = {{2, "near", 1, 0.8}};  // stored from the door's side
  // label 1, embedding falls back to label 1, detector 0.85 * min(1, 15/10), spatial 1:
  // 0.35 + 0.35 + 0.15 * 0.85 + 0.15 = 0.9775
  ScoredObject scored =
      resolver_.Score(Target("灭火器", {"红色"}, "near", "door"), graph.objects[0], graph, {});
  EXPECT_DOUBLE_EQ(scored.label, 1.0);
  EXPECT_DOUBLE_EQ(scored.embedding, 1.0);
  EXPECT_DOUBLE_EQ(scored.detector, 0.85);
  EXPECT_DOUBLE_EQ(scored.spatial, 1.0);
  EXPECT_NEAR(scored.fused, 0.9775, 1e-12);
}

TEST_F(GatewayFastResolverTest, EmbeddingCosineReplacesTheFallback) {
  SceneGraph graph;
  graph.objects = {Object(1, "sofa", 0.8, 5)};
  graph.objects[0].embedding = {0.6f, 0.8f};
  // cos([1,0],[0.6,0.8]) = 0.6; detector 0.8 * 0.5 = 0.4; no relation asked -> spatial 0.
  // 0.35 * 1 + 0.35 * 0.6 + 0.15 * 0.4 + 0 = 0.62 -> slow path.
  FastResolution resolution = resolver_.Resolve(Target("couch"), graph, {1.0f, 0.0f}, {});
  ASSERT_TRUE(resolution.best.has_value());
  EXPECT_NEAR(resolution.best->embedding, 0.6, 1e-6);
  EXPECT_NEAR(resolution.best->fused, 0.62, 1e-6);
  EXPECT_FALSE(resolution.accepted);
}

TEST_F(GatewayFastResolverTest, ThresholdIsStrictlyAboveSeventyFivePercent) {
  SceneGraph graph;
  // 0.7 + 0.15 * 0.9 * 0.5 = 0.7675 -> accepted; with 3 detections 0.7 + 0.15 * 0.27 = 0.7405 ->
  // not.
  graph.objects = {Object(7, "cup", 0.9, 5)};
  EXPECT_TRUE(resolver_.Resolve(Target("杯子"), graph, {}, {}).accepted);
  graph.objects[0].detection_count = 3;
  FastResolution low = resolver_.Resolve(Target("杯子"), graph, {}, {});
  EXPECT_NEAR(low.best->fused, 0.7405, 1e-12);
  EXPECT_FALSE(low.accepted);
}

TEST_F(GatewayFastResolverTest, ColoursSelectAmongSameLabelObjects) {
  SceneGraph graph;
  graph.objects = {Object(1, "blue cup", 0.95, 20), Object(2, "cup", 0.95, 20, {"red"}),
                   Object(3, "cup", 0.95, 20)};
  FastResolution red = resolver_.Resolve(Target("cup", {"red"}), graph, {}, {});
  EXPECT_EQ(red.best->object_id, 2);
  EXPECT_TRUE(red.accepted);
  // Excluding the red one leaves the cup of unknown colour: label 0.5 -> 0.35 + 0.1425 = 0.4925.
  FastResolution other = resolver_.Resolve(Target("cup", {"red"}), graph, {}, {2});
  EXPECT_EQ(other.best->object_id, 3);
  EXPECT_NEAR(other.best->fused, 0.4925, 1e-12);
  EXPECT_FALSE(other.accepted);
}

TEST_F(GatewayFastResolverTest, SpatialHintPicksTheChairLeftOfTheSofa) {
  SceneGraph graph;
  graph.objects = {Object(1, "chair", 0.9, 10), Object(2, "chair", 0.9, 10),
                   Object(3, "couch", 0.9, 10)};
  graph.relations = {{3, "right_of", 2, 1.0}, {1, "near", 3, 2.0}};  // couch right_of chair 2
  FastResolution resolution =
      resolver_.Resolve(Target("chair", {}, "left_of", "沙发"), graph, {}, {});
  EXPECT_EQ(resolution.best->object_id, 2);
  EXPECT_NEAR(resolution.best->fused, 0.35 + 0.35 + 0.135 + 0.15, 1e-12);
}

TEST_F(GatewayFastResolverTest, NothingMatchingMeansNoCandidate) {
  SceneGraph graph;
  graph.objects = {Object(1, "chair", 0.9, 10)};
  FastResolution resolution = resolver_.Resolve(Target("backpack"), graph, {}, {});
  EXPECT_FALSE(resolution.best.has_value());
  EXPECT_FALSE(resolution.accepted);
}

TEST(GatewayCosineTest, HandValues) {
  EXPECT_DOUBLE_EQ(Cosine({1, 0}, {0, 1}), 0.0);
  EXPECT_NEAR(Cosine({1, 1}, {1, 0}), 1.0 / std::sqrt(2.0), 1e-7);
  EXPECT_EQ(Cosine({1, 0}, {1, 0, 0}), 0.0);
  EXPECT_EQ(Cosine({}, {}), 0.0);
}

}  // namespace
}  // namespace semnav::reasoning
