#include "services/mapping/core/object_visibility.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::mapping {
namespace {

// A 160 x 120 camera at the origin looking along map +x (optical z = map x, optical x = map -y,
// optical y = map -z), fx = fy = 100: 1.6 rad wide. A wall 5 m away fills the depth image.
struct Camera {
  Intrinsics k{160, 120, 100.0, 100.0, 80.0, 60.0};
  CameraPose pose;
  cv::Mat depth = cv::Mat(120, 160, CV_32F, cv::Scalar(5.0f));
  Camera() {
    Eigen::Matrix3d map_from_optical;
    map_from_optical << 0, 0, 1, -1, 0, 0, 0, -1, 0;
    pose.orientation = Eigen::Quaterniond(map_from_optical);
  }
};

SceneObject Box(Eigen::Vector3d centre, double edge) {
  SceneObject object;
  object.position = centre;
  object.size = Eigen::Vector3d::Constant(edge);
  return object;
}

TEST(ObjectVisibilityTest, AnUnhiddenObjectAheadIsExpected) {
  const Camera camera;
  const ExistenceConfig config;
  // 2 m ahead, 0.5 m cube: 25 x 25 px = 625 px >= 0.002 x 19200 = 38.4 px.
  EXPECT_TRUE(ExpectedInView(Box({2, 0, 0}, 0.5), camera.depth, camera.k, camera.pose, config));
}

TEST(ObjectVisibilityTest, BehindTooFarTooSmallOrAtTheEdgeIsNot) {
  const Camera camera;
  const ExistenceConfig config;
  const auto expected = [&](const SceneObject& o) {
    return ExpectedInView(o, camera.depth, camera.k, camera.pose, config);
  };
  EXPECT_FALSE(expected(Box({-2, 0, 0}, 0.5)));   // behind the camera
  EXPECT_FALSE(expected(Box({4.5, 0, 0}, 0.5)));  // beyond max_range_m 4
  // 0.02 m at 3 m: 0.67 x 0.67 px, below 38.4 px.
  EXPECT_FALSE(expected(Box({3, 0, 0}, 0.02)));
  // Left by 0.75 m at 2 m: u = 80 - 100 * 0.75 / 2 = 42.5 >= 16 (margin): in view ...
  EXPECT_TRUE(expected(Box({2, 0.75, 0}, 0.5)));
  // ... 1.4 m: u = 10 < 16, too near the edge to count.
  EXPECT_FALSE(expected(Box({2, 1.4, 0}, 0.5)));
}

// Regression (mission bench: false "refrigerator" and "car" detections lifted onto the floor got
// a box 0.01 m high; width x height gave them no area, so no frame ever counted against them).
TEST(ObjectVisibilityTest, AFlatBoxOnTheFloorAheadHasTheAreaItCovers) {
  const Camera camera;
  SceneObject mat = Box({2, 0, -0.5}, 0.5);
  mat.size.z() = 0.0;
  // u: 80 -+ 100 x 0.25 / 1.75 -> 28.57 px; v: 60 + 100 x 0.5 / 2.25 .. / 1.75 -> 6.35 px.
  EXPECT_NEAR(ApparentArea(mat, camera.k, camera.pose, 160, 120),
              (200.0 * 0.25 / 1.75) * (50.0 / 1.75 - 50.0 / 2.25), 1e-6);
  EXPECT_TRUE(ExpectedInView(mat, camera.depth, camera.k, camera.pose, ExistenceConfig{}));
  // The 0.5 m cube 2 m ahead: its near face's corners span 28.57 px both ways.
  EXPECT_NEAR(ApparentArea(Box({2, 0, 0}, 0.5), camera.k, camera.pose, 160, 120),
              std::pow(200.0 * 0.25 / 1.75, 2), 1e-6);
  // Larger than the image: clipped to it.
  EXPECT_DOUBLE_EQ(ApparentArea(Box({1, 0, 0}, 10.0), camera.k, camera.pose, 160, 120),
                   160.0 * 120.0);
}

TEST(ObjectVisibilityTest, HiddenBySomethingNearerOrNoReadingIsNot) {
  Camera camera;
  const ExistenceConfig config;
  const SceneObject object = Box({3, 0, 0}, 0.4);  // front at 2.8 m, counted from 2.5 m
  camera.depth.at<float>(60, 80) = 2.6f;           // its own front, with noise: seen
  EXPECT_TRUE(ExpectedInView(object, camera.depth, camera.k, camera.pose, config));
  camera.depth.at<float>(60, 80) = 2.4f;  // a chair between: hidden
  EXPECT_FALSE(ExpectedInView(object, camera.depth, camera.k, camera.pose, config));
  camera.depth.at<float>(60, 80) = 0.0f;  // no reading: no evidence
  EXPECT_FALSE(ExpectedInView(object, camera.depth, camera.k, camera.pose, config));
  camera.depth.at<float>(60, 80) = NAN;
  EXPECT_FALSE(ExpectedInView(object, camera.depth, camera.k, camera.pose, config));
}

}  // namespace
}  // namespace semnav::mapping
