#include "clients/sim/core/detector.h"

#include <gtest/gtest.h>

#include "clients/sim/core/class_embedding.h"
#include "clients/sim/core/test_worlds.h"

namespace semnav::sim {
namespace {

using testing::Box;

DetectorConfig Exact() {
  DetectorConfig config;
  config.miss_rate = 0.0;
  config.false_positive_rate = 0.0;
  config.confusion_rate = 0.0;
  config.box_noise_px = 0.0;
  config.depth_noise_m = 0.0;
  return config;
}

class SimDetectorTest : public ::testing::Test {
 protected:
  SimDetectorTest() {
    world_ = testing::OpenWorld();
    // A 0.6 m chair-sized box whose front face is 2.7 m ahead of a camera 0.5 m up.
    world_.objects.push_back(testing::Object("chair_1", "chair", Box(3.0, 0.0, 0.6, 0.6, 1.0)));
  }
  DetectionFrame Detect(const DetectorConfig& config, uint64_t seed = 1) {
    scene_ = Scene::Build(world_);
    const RenderedView view =
        RenderView(scene_, k_, CameraPoseInWorld({0, 0, 0.5}, 0, 0), 0.3, 8.0);
    return DetectObjects(view, scene_, world_, config, seed);
  }
  World world_;
  Scene scene_;
  CameraIntrinsics k_;
};

TEST_F(SimDetectorTest, VisibleObjectProjectsWhereThePinholeSays) {
  const DetectionFrame frame = Detect(Exact());
  ASSERT_EQ(frame.detections.size(), 1u);
  const Detection& d = frame.detections[0];
  EXPECT_EQ(d.label, "chair");
  EXPECT_EQ(d.object_index, 0);
  EXPECT_NEAR(d.depth_m, 2.7, 1e-4);
  // u = cx +- fx * 0.3 / 2.7, v = cy - fy * (z - 0.5) / 2.7 for z = 1 and z = 0.
  EXPECT_NEAR(d.box[0], 319.5 - 525 * 0.3 / 2.7, 1.0);
  EXPECT_NEAR(d.box[2], 319.5 + 525 * 0.3 / 2.7, 1.0);
  EXPECT_NEAR(d.box[1], 239.5 - 525 * 0.5 / 2.7, 1.0);
  EXPECT_NEAR(d.box[3], 239.5 + 525 * 0.5 / 2.7, 1.0);
  EXPECT_NEAR(d.position_camera.z(), 2.7, 1e-4);
  EXPECT_NEAR(d.position_camera.x(), 0.0, 0.01);
  EXPECT_EQ(frame.mask[240 * 640 + 320], 1);
  EXPECT_EQ(frame.mask[0], 0);
}

TEST_F(SimDetectorTest, StuffKindsAreOneSegmentPerClassAndNeverAnObject) {
  // Two 2 cm road strips crossing the view 1.5-2.0 m and 3.5-4.5 m ahead; a wall is not stuff.
  world_.obstacles.push_back(Obstacle{"road", Rgb{}, Box(1.75, 0.0, 0.5, 4.0, 0.02)});
  world_.obstacles.push_back(Obstacle{"road", Rgb{}, Box(4.0, 0.0, 1.0, 4.0, 0.02)});
  world_.obstacles.push_back(Obstacle{"wall", Rgb{}, Box(6.0, 0.0, 0.1, 8.0, 2.5)});
  const DetectionFrame frame = Detect(Exact());
  ASSERT_EQ(frame.detections.size(), 2u);
  EXPECT_EQ(frame.detections[0].label, "chair");
  const Detection& road = frame.detections[1];
  EXPECT_EQ(road.label, "road");
  EXPECT_EQ(road.object_index, -1);
  // One box over both strips: from the far strip's top edge (row of the 4.5 m ground point,
  // hidden partly behind the chair's sides) down to the near strip's nearest row at 1.5 m.
  EXPECT_NEAR(road.box[3], 239.5 + 525 * 0.5 / 1.5, 2.0);
  EXPECT_NEAR(road.box[1], 239.5 + 525 * 0.48 / 4.5, 2.0);
  DetectorConfig no_stuff = Exact();
  no_stuff.stuff_kinds.clear();
  EXPECT_EQ(Detect(no_stuff).detections.size(), 1u);
}

TEST_F(SimDetectorTest, OccludedOrTinyObjectsAreNotDetected) {
  world_.obstacles.push_back(Obstacle{"wall", Rgb{}, Box(1.5, 0.0, 0.1, 3.0, 2.5)});
  EXPECT_TRUE(Detect(Exact()).detections.empty());
  world_.obstacles.clear();
  DetectorConfig config = Exact();
  config.min_pixels = 1000000;
  EXPECT_TRUE(Detect(config).detections.empty());
}

TEST_F(SimDetectorTest, MissesConfusionsAndFalsePositives) {
  DetectorConfig config = Exact();
  config.miss_rate = 1.0;
  EXPECT_TRUE(Detect(config).detections.empty());
  config = Exact();
  config.confusion_rate = 1.0;
  const DetectionFrame confused = Detect(config);
  ASSERT_EQ(confused.detections.size(), 1u);
  EXPECT_NE(confused.detections[0].label, "chair");
  // The embedding still describes what the object really is.
  const auto chair = ClassEmbedding("chair", config.embedding_dim, config.embedding_seed);
  const auto other =
      ClassEmbedding(confused.detections[0].label, config.embedding_dim, config.embedding_seed);
  EXPECT_GT(CosineSimilarity(confused.detections[0].embedding, chair), 0.9);
  EXPECT_LT(CosineSimilarity(confused.detections[0].embedding, other), 0.5);
  config = Exact();
  config.false_positive_rate = 20.0;
  const DetectionFrame noisy = Detect(config);
  int false_positives = 0;
  for (const Detection& d : noisy.detections) false_positives += d.object_index < 0 ? 1 : 0;
  EXPECT_GT(false_positives, 5);
}

TEST_F(SimDetectorTest, SameSeedSameDetections) {
  DetectorConfig config;
  config.false_positive_rate = 3.0;
  const DetectionFrame a = Detect(config, 42);
  const DetectionFrame b = Detect(config, 42);
  ASSERT_EQ(a.detections.size(), b.detections.size());
  for (size_t i = 0; i < a.detections.size(); ++i) {
    EXPECT_EQ(a.detections[i].label, b.detections[i].label);
    EXPECT_EQ(a.detections[i].box, b.detections[i].box);
    EXPECT_EQ(a.detections[i].embedding, b.detections[i].embedding);
    EXPECT_EQ(a.detections[i].score, b.detections[i].score);
  }
}

TEST(SimClassEmbeddingTest, DeterministicAndDistinctPerClass) {
  const auto a = ClassEmbedding("chair", 64, 1);
  EXPECT_EQ(a, ClassEmbedding("chair", 64, 1));
  EXPECT_NEAR(CosineSimilarity(a, a), 1.0, 1e-6);
  EXPECT_LT(std::abs(CosineSimilarity(a, ClassEmbedding("bed", 64, 1))), 0.5);
  EXPECT_NE(a, ClassEmbedding("chair", 64, 2));
}

}  // namespace
}  // namespace semnav::sim
