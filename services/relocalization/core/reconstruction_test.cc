#include "services/relocalization/core/reconstruction.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace semnav::relocalization {
namespace {

using ::testing::HasSubstr;

TEST(RelocReconstructionTest, BackProjectsWithMetricScale) {
  ObjectPoint point;
  point.u = 420.0;                           // 100 px right of the principal point
  point.v = 190.0;                           // 50 px above it
  point.box = {400.0, 170.0, 440.0, 230.0};  // 40 x 60 px
  point.descriptor = {0.2f, 0.8f};
  const PinholeCamera camera{500.0, 600.0, 320.0, 240.0};
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  world_from_camera.translation() = Eigen::Vector3d(10.0, 0.0, 1.0);
  const auto l = ReconstructLandmark(point, 2.5, camera, world_from_camera);
  ASSERT_TRUE(l.ok()) << l.status();
  EXPECT_NEAR(l->position.x(), 10.5, 1e-12);  // 10 + 2.5 * 100 / 500
  EXPECT_NEAR(l->position.y(), -2.5 * 50 / 600, 1e-12);
  EXPECT_NEAR(l->position.z(), 3.5, 1e-12);
  EXPECT_NEAR(l->scale, 0.5 * (40.0 / 500 + 60.0 / 600) * 2.5, 1e-12);  // 0.225 m
  EXPECT_EQ(l->descriptor, point.descriptor);
}

TEST(RelocReconstructionTest, RejectsBadDepthAndCamera) {
  const auto bad_depth =
      ReconstructLandmark({}, 0.0, {500, 500, 320, 240}, Eigen::Isometry3d::Identity());
  EXPECT_EQ(bad_depth.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(bad_depth.status().message(), HasSubstr("depth_m"));
  const auto bad_camera =
      ReconstructLandmark({}, 1.0, {0, 500, 320, 240}, Eigen::Isometry3d::Identity());
  EXPECT_THAT(bad_camera.status().message(), HasSubstr("camera"));
}

Landmark At(double x, Descriptor d) {
  Landmark l;
  l.position = {x, 0.0, 0.0};
  l.scale = 0.3;
  l.descriptor = std::move(d);
  return l;
}

TEST(RelocReconstructionTest, TrackerKeepsOnlyPointsStableForThreeFrames) {
  StableLandmarkTracker tracker(TrackerParams{});  // 3 frames, 0.3 m, cosine 0.7
  EXPECT_TRUE(tracker.AddFrame({At(0.0, {1, 0}), At(5.0, {0, 1})}).empty());
  // The second object flickers away; the first moves 0.1 m.
  EXPECT_TRUE(tracker.AddFrame({At(0.1, {1, 0})}).empty());
  const auto stable = tracker.AddFrame({At(0.2, {1, 0}), At(5.0, {0, 1})});
  ASSERT_EQ(stable.size(), 1u);
  EXPECT_NEAR(stable[0].position.x(), 0.1, 1e-12);  // mean of 0, 0.1, 0.2
  EXPECT_EQ(stable[0].observations, 3u);
  // Reported once; the restarted second track needs two more frames.
  EXPECT_TRUE(tracker.AddFrame({At(0.2, {1, 0}), At(5.0, {0, 1})}).empty());
  const auto second = tracker.AddFrame({At(5.0, {0, 1})});
  ASSERT_EQ(second.size(), 1u);
  EXPECT_NEAR(second[0].position.x(), 5.0, 1e-12);
}

TEST(RelocReconstructionTest, TrackerGateRejectsDifferentDescriptor) {
  StableLandmarkTracker tracker(TrackerParams{});
  tracker.AddFrame({At(0.0, {1, 0})});
  tracker.AddFrame({At(0.0, {0, 1})});  // same place, other object: a new track
  EXPECT_TRUE(tracker.AddFrame({At(0.0, {0, 1})}).empty());
  EXPECT_EQ(tracker.AddFrame({At(0.0, {0, 1})}).size(), 1u);
}

}  // namespace
}  // namespace semnav::relocalization
