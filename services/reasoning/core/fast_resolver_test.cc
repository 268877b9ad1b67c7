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
  graph.objects[0].embedding = {0.6f, 0.8f};
  graph.relations = {{2, "near", 1, 0.8}};  // stored from the door's side
  // label 1, embedding cos([0.6,0.8],[0.6,0.8]) = 1, detector 0.85 * min(1, 15/10), spatial 1:
  // every term applies, the seed's sum 0.35 + 0.35 + 0.15 * 0.85 + 0.15 = 0.9775
  ScoredObject scored = resolver_.Score(Target("灭火器", {"红色"}, "near", "door"),
                                        graph.objects[0], graph, {0.6f, 0.8f});
  EXPECT_DOUBLE_EQ(scored.label, 1.0);
  EXPECT_NEAR(scored.embedding, 1.0, 1e-6);
  EXPECT_DOUBLE_EQ(scored.detector, 0.85);
  EXPECT_DOUBLE_EQ(scored.spatial, 1.0);
  EXPECT_NEAR(scored.fused, 0.9775, 1e-6);
}

// Without a text embedding the CLIP term is left out (not stood in for by the label match):
// (0.35 * 1 + 0.15 * 0.85 + 0.15 * 1) / 0.65 = 0.6275 / 0.65.
TEST_F(GatewayFastResolverTest, MissingEmbeddingIsLeftOutAndTheWeightsRenormalised) {
  SceneGraph graph;
  graph.objects = {Object(1, "fire_extinguisher", 0.85, 15, {"red"}), Object(2, "door", 0.9, 20)};
  graph.relations = {{2, "near", 1, 0.8}};
  ScoredObject scored =
      resolver_.Score(Target("灭火器", {"红色"}, "near", "door"), graph.objects[0], graph, {});
  EXPECT_DOUBLE_EQ(scored.embedding, 0.0);
  EXPECT_NEAR(scored.fused, 0.6275 / 0.65, 1e-12);
}

TEST_F(GatewayFastResolverTest, EmbeddingCosineCountsWhenBothVectorsExist) {
  SceneGraph graph;
  graph.objects = {Object(1, "sofa", 0.8, 5)};
  graph.objects[0].embedding = {0.6f, 0.8f};
  // cos([1,0],[0.6,0.8]) = 0.6; detector 0.8 * 0.5 = 0.4; no relation asked -> no spatial term.
  // (0.35 * 1 + 0.35 * 0.6 + 0.15 * 0.4) / 0.85 = 0.62 / 0.85 = 0.729 -> slow path.
  FastResolution resolution = resolver_.Resolve(Target("couch"), graph, {1.0f, 0.0f}, {});
  ASSERT_TRUE(resolution.best.has_value());
  EXPECT_NEAR(resolution.best->embedding, 0.6, 1e-6);
  EXPECT_NEAR(resolution.best->fused, 0.62 / 0.85, 1e-6);
  EXPECT_FALSE(resolution.accepted);
}

// A detection whose label says cup but whose appearance is another class's (the detector confused
// it) is not taken on its label: the embedding disagrees, (0.35 + 0 + 0.15 * 0.9) / 0.85 = 0.571.
// The same object with a matching appearance passes at its first detection:
// (0.35 + 0.35 + 0.15 * 0.09) / 0.85 = 0.8394.
TEST_F(GatewayFastResolverTest, AnEmbeddingThatDisagreesWithTheLabelSendsItToTheSlowPath) {
  SceneGraph graph;
  graph.objects = {Object(7, "cup", 0.9, 10)};
  graph.objects[0].embedding = {0.0f, 1.0f};
  FastResolution confused = resolver_.Resolve(Target("cup"), graph, {1.0f, 0.0f}, {});
  EXPECT_NEAR(confused.best->fused, 0.485 / 0.85, 1e-6);
  EXPECT_FALSE(confused.accepted);
  graph.objects[0].embedding = {1.0f, 0.0f};
  graph.objects[0].detection_count = 1;
  FastResolution seen_once = resolver_.Resolve(Target("cup"), graph, {1.0f, 0.0f}, {});
  EXPECT_NEAR(seen_once.best->fused, 0.7135 / 0.85, 1e-6);
  EXPECT_TRUE(seen_once.accepted);
}

// Issue 15's regression: with the spatial term fixed at 0 for a target that names no relation,
// an exact label without embeddings needed 5 detections (0.7 + 0.15 * 0.9 * 0.5 = 0.7675) and the
// slow path was asked first. Now label and detector alone: (0.35 + 0.15 * 0.9 * 0.2) / 0.5 = 0.754
// passes at 2 detections, (0.35 + 0.15 * 0.09) / 0.5 = 0.727 at 1 does not.
TEST_F(GatewayFastResolverTest, ThresholdIsStrictlyAboveSeventyFivePercent) {
  SceneGraph graph;
  graph.objects = {Object(7, "cup", 0.9, 2)};
  FastResolution two = resolver_.Resolve(Target("杯子"), graph, {}, {});
  EXPECT_NEAR(two.best->fused, 0.754, 1e-12);
  EXPECT_TRUE(two.accepted);
  graph.objects[0].detection_count = 1;
  FastResolution low = resolver_.Resolve(Target("杯子"), graph, {}, {});
  EXPECT_NEAR(low.best->fused, 0.727, 1e-12);
  EXPECT_FALSE(low.accepted);
}

TEST_F(GatewayFastResolverTest, ColoursSelectAmongSameLabelObjects) {
  SceneGraph graph;
  graph.objects = {Object(1, "blue cup", 0.95, 20), Object(2, "cup", 0.95, 20, {"red"}),
                   Object(3, "cup", 0.95, 20)};
  FastResolution red = resolver_.Resolve(Target("cup", {"red"}), graph, {}, {});
  EXPECT_EQ(red.best->object_id, 2);
  EXPECT_TRUE(red.accepted);
  // Excluding the red one leaves the cup of unknown colour: label 0.5 ->
  // (0.175 + 0.1425) / 0.5 = 0.635.
  FastResolution other = resolver_.Resolve(Target("cup", {"red"}), graph, {}, {2});
  EXPECT_EQ(other.best->object_id, 3);
  EXPECT_NEAR(other.best->fused, 0.635, 1e-12);
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
  EXPECT_NEAR(resolution.best->fused, (0.35 + 0.135 + 0.15) / 0.65, 1e-12);
  EXPECT_TRUE(resolution.accepted);
  // The chair whose relation the graph does not hold stays below: (0.35 + 0.135) / 0.65 = 0.746.
  FastResolution other = resolver_.Resolve(Target("chair", {}, "left_of", "沙发"), graph, {}, {2});
  EXPECT_EQ(other.best->object_id, 1);
  EXPECT_NEAR(other.best->fused, 0.485 / 0.65, 1e-12);
  EXPECT_FALSE(other.accepted);
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
