#include "services/mapping/landmarks/scene_landmarks.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "services/common/status/field_error.h"

namespace semnav::mapping {
namespace {

using ::testing::ElementsAre;
using ::testing::FloatNear;
using ::testing::HasSubstr;

SceneObject Chair() {
  SceneObject o;
  o.id = 7;
  o.label = "chair";
  o.position = Eigen::Vector3d(1.0, 2.0, 0.45);
  o.size = Eigen::Vector3d(0.3, 0.4, 1.2);  // diagonal sqrt(0.09 + 0.16 + 1.44) = 1.3
  o.detection_count = 4;
  o.label_scores = {{"chair", 3.0}, {"couch", 1.0}};  // shares 0.75 / 0.25
  o.embedding = {3.0f, 4.0f};                         // unit (0.6, 0.8)
  return o;
}

SceneLandmarkConfig TwoLabelsTwoDims() {
  SceneLandmarkConfig config;
  config.labels = {"couch", "chair"};
  config.embedding_dim = 2;
  config.embedding_weight = 0.5;
  config.min_detections = 3;
  return config;
}

TEST(SceneLandmarks, InstanceBecomesLabelSharesThenWeightedUnitEmbedding) {
  const std::vector<SceneLandmark> out = LandmarksFromScene({Chair()}, TwoLabelsTwoDims());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].object_id, 7u);
  const relocalization::Landmark& l = out[0].landmark;
  EXPECT_EQ(l.id, 0u);
  EXPECT_EQ(l.position, Eigen::Vector3d(1.0, 2.0, 0.45));
  EXPECT_NEAR(l.scale, 1.3, 1e-12);
  EXPECT_EQ(l.observations, 4u);
  // [couch 0.25, chair 0.75 | 0.5 * 0.6, 0.5 * 0.8]
  EXPECT_THAT(l.descriptor, ElementsAre(FloatNear(0.25f, 1e-6), FloatNear(0.75f, 1e-6),
                                        FloatNear(0.3f, 1e-6), FloatNear(0.4f, 1e-6)));
  // The hash key of seed 001 is the instance's best label, not an embedding entry.
  EXPECT_EQ(relocalization::DescriptorLabel(l.descriptor), 1);
}

TEST(SceneLandmarks, ScoreMassOutsideTheListStaysOutOfTheShares) {
  SceneObject o = Chair();
  o.label_scores = {{"chair", 2.0}, {"stool", 2.0}};
  SceneLandmarkConfig config = TwoLabelsTwoDims();
  config.embedding_dim = 0;
  const std::vector<SceneLandmark> out = LandmarksFromScene({o}, config);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_THAT(out[0].landmark.descriptor, ElementsAre(0.0f, FloatNear(0.5f, 1e-6)));
}

TEST(SceneLandmarks, WithoutScoreHistoryTheLabelCountsWhole) {
  SceneObject o = Chair();
  o.label_scores.clear();
  SceneLandmarkConfig config = TwoLabelsTwoDims();
  config.embedding_dim = 0;
  const std::vector<SceneLandmark> out = LandmarksFromScene({o}, config);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_THAT(out[0].landmark.descriptor, ElementsAre(0.0f, 1.0f));
}

TEST(SceneLandmarks, OnlyStableInstancesBecomeLandmarks) {
  SceneObject seen_twice = Chair();
  seen_twice.id = 8;
  seen_twice.detection_count = 2;
  const std::vector<SceneLandmark> out =
      LandmarksFromScene({seen_twice, Chair()}, TwoLabelsTwoDims());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].object_id, 7u);
}

// Instances seen while the robot was lost may sit in the wrong frame: never landmarks (before,
// relocalization matched a lost robot's look-around against itself in mapping's live map).
TEST(SceneLandmarks, InstancesSeenWhileThePoseWasUntrustedAreLeftOut) {
  SceneObject while_lost = Chair();
  while_lost.id = 9;
  while_lost.pose_untrusted = true;
  const std::vector<SceneLandmark> out =
      LandmarksFromScene({while_lost, Chair()}, TwoLabelsTwoDims());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].object_id, 7u);
}

// The live push waits until an instance has not been seen for settle_s: a loss reported 2.5 s late
// must be able to mark what the robot saw meanwhile before it reaches the landmark map.
TEST(SceneLandmarks, OnlyInstancesUnseenForTheSettleTimeAreSettled) {
  SceneObject old_one = Chair();
  old_one.last_seen_ns = 1'000'000'000;  // 1 s
  SceneObject edge = Chair();
  edge.id = 8;
  edge.last_seen_ns = 3'500'000'000;  // 2.5 s before the newest: settled
  SceneObject recent = Chair();
  recent.id = 9;
  recent.last_seen_ns = 6'000'000'000;  // the newest observation
  const std::vector<SceneObject> settled = SettledInstances({old_one, edge, recent}, 2.5);
  ASSERT_EQ(settled.size(), 2u);
  EXPECT_EQ(settled[0].id, 7u);
  EXPECT_EQ(settled[1].id, 8u);
  EXPECT_EQ(SettledInstances({old_one, edge, recent}, 0.0).size(), 3u);
}

TEST(SceneLandmarks, EmbeddingOfAnotherLengthLeavesZerosAndNothingDescribableIsSkipped) {
  SceneObject other_dim = Chair();
  other_dim.embedding = {1.0f, 0.0f, 0.0f};
  const std::vector<SceneLandmark> out = LandmarksFromScene({other_dim}, TwoLabelsTwoDims());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_THAT(out[0].landmark.descriptor,
              ElementsAre(FloatNear(0.25f, 1e-6), FloatNear(0.75f, 1e-6), 0.0f, 0.0f));

  SceneLandmarkConfig embedding_only;
  embedding_only.labels = {};
  embedding_only.embedding_dim = 2;
  SceneObject no_embedding = Chair();
  no_embedding.embedding.clear();
  EXPECT_TRUE(LandmarksFromScene({no_embedding}, embedding_only).empty());
}

TEST(SceneLandmarks, BadGeometryIsLeftOut) {
  SceneObject flat = Chair();
  flat.size = Eigen::Vector3d::Zero();
  SceneObject far = Chair();
  far.position.x() = 1e9;
  SceneObject nan = Chair();
  nan.position.y() = std::numeric_limits<double>::quiet_NaN();
  SceneObject bad_embedding = Chair();
  bad_embedding.embedding = {std::numeric_limits<float>::infinity(), 1.0f};
  const std::vector<SceneLandmark> out =
      LandmarksFromScene({flat, far, nan, bad_embedding}, TwoLabelsTwoDims());
  ASSERT_EQ(out.size(), 1u);  // the infinite embedding is dropped, the label shares remain
  EXPECT_THAT(out[0].landmark.descriptor,
              ElementsAre(FloatNear(0.25f, 1e-6), FloatNear(0.75f, 1e-6), 0.0f, 0.0f));
}

TEST(SceneLandmarks, ConfigIsCheckedAtTheDoor) {
  EXPECT_TRUE(ValidateSceneLandmarkConfig(SceneLandmarkConfig{}).ok());
  SceneLandmarkConfig c = TwoLabelsTwoDims();
  c.labels = {"chair", "chair"};
  EXPECT_EQ(ErrorField(ValidateSceneLandmarkConfig(c)), "labels[1]");
  c = TwoLabelsTwoDims();
  c.labels = {""};
  EXPECT_EQ(ErrorField(ValidateSceneLandmarkConfig(c)), "labels[0]");
  c = TwoLabelsTwoDims();
  c.labels.clear();
  c.embedding_dim = 0;
  EXPECT_EQ(ErrorField(ValidateSceneLandmarkConfig(c)), "embedding_dim");
  c.embedding_dim = 5000;
  EXPECT_THAT(std::string(ValidateSceneLandmarkConfig(c).message()), HasSubstr("descriptor limit"));
  c = TwoLabelsTwoDims();
  c.min_detections = 0;
  EXPECT_EQ(ErrorField(ValidateSceneLandmarkConfig(c)), "min_detections");
  c = TwoLabelsTwoDims();
  c.embedding_weight = std::nan("");
  EXPECT_EQ(ErrorField(ValidateSceneLandmarkConfig(c)), "embedding_weight");
  EXPECT_EQ(SceneLandmarkDescriptorDim(TwoLabelsTwoDims()), 4u);
}

}  // namespace
}  // namespace semnav::mapping
