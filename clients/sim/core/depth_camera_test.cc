// The rendered view and the depth image: geometry against hand-computed values, noise, RGB.
#include <gtest/gtest.h>

#include <cmath>

#include "clients/sim/core/depth_noise.h"
#include "clients/sim/core/ray_caster.h"
#include "clients/sim/core/rgb_image.h"
#include "clients/sim/core/test_worlds.h"
#include "clients/sim/core/view_renderer.h"

namespace semnav::sim {
namespace {

using testing::Box;

size_t Pixel(const CameraIntrinsics& k, int u, int v) {
  return static_cast<size_t>(v) * k.width + u;
}

TEST(SimDepthCameraTest, FrontoParallelWallHasConstantDepth) {
  World world = testing::OpenWorld();
  // Wall face at x = 3, tall and wide enough to fill the view.
  world.obstacles.push_back(Obstacle{"wall", Rgb{}, Box(3.5, 0, 1.0, 20.0, 6.0)});
  world.ceiling_height = 0.0;
  const Scene scene = Scene::Build(world);
  CameraIntrinsics k;
  const auto pose = CameraPoseInWorld({0, 0, 1.5}, 0.0, 0.0);
  const RenderedView view = RenderView(scene, k, pose, 0.3, 8.0);
  // z-depth (not ray length) is 3 m everywhere on the wall, including the corners.
  EXPECT_NEAR(view.depth[Pixel(k, 320, 240)], 3.0, 1e-5);
  EXPECT_NEAR(view.depth[Pixel(k, 0, 0)], 3.0, 1e-5);
  EXPECT_NEAR(view.depth[Pixel(k, 639, 479)], 3.0, 1e-5);
  EXPECT_EQ(view.surface[Pixel(k, 0, 0)], 0);
}

TEST(SimDepthCameraTest, RangeLimitsBlankTooNearAndTooFar) {
  World world = testing::OpenWorld();
  world.obstacles.push_back(Obstacle{"wall", Rgb{}, Box(9.0, 0, 1.0, 40.0, 9.0)});  // face x=8.5
  const Scene scene = Scene::Build(world);
  CameraIntrinsics k;
  const RenderedView far = RenderView(scene, k, CameraPoseInWorld({0, 0, 4.0}, 0, 0), 0.3, 8.0);
  EXPECT_EQ(far.depth[Pixel(k, 320, 240)], 0.0f);
  EXPECT_EQ(far.surface[Pixel(k, 320, 240)], kNoSurface);
  // 0.2 m from the face: closer than the 0.3 m minimum.
  const RenderedView near = RenderView(scene, k, CameraPoseInWorld({8.3, 0, 4.0}, 0, 0), 0.3, 8.0);
  EXPECT_EQ(near.depth[Pixel(k, 320, 240)], 0.0f);
  const RenderedView ok = RenderView(scene, k, CameraPoseInWorld({5.0, 0, 4.0}, 0, 0), 0.3, 8.0);
  EXPECT_NEAR(ok.depth[Pixel(k, 320, 240)], 3.5, 1e-5);
}

TEST(SimDepthCameraTest, FloorSeenBelowTheHorizon) {
  const World world = testing::OpenWorld();
  const Scene scene = Scene::Build(world);
  CameraIntrinsics k;
  const RenderedView view = RenderView(scene, k, CameraPoseInWorld({0, 0, 1.0}, 0, 0), 0.3, 8.0);
  // Row v looks down by atan((v - cy) / fy); the floor 1 m below is at z-depth fy / (v - cy).
  const int v = 400;
  EXPECT_NEAR(view.depth[Pixel(k, 320, v)], k.fy / (v - k.cy), 1e-4);
  EXPECT_EQ(view.surface[Pixel(k, 320, v)], kFloorSurface);
  EXPECT_EQ(view.depth[Pixel(k, 320, 100)], 0.0f);  // open sky above the horizon
}

TEST(SimDepthCameraTest, NoiseGrowsWithDistanceAndIsSeeded) {
  DepthNoiseModel model;
  EXPECT_NEAR(model.Sigma(1.0), 0.0012 + 0.0019 * 0.36, 1e-12);
  EXPECT_GT(model.Sigma(4.0), 10 * model.Sigma(1.0));
  RenderedView view;
  view.depth.assign(20000, 4.0f);
  const std::vector<float> a = NoisyDepth(view, model, 0.3, 8.0, 5);
  const std::vector<float> b = NoisyDepth(view, model, 0.3, 8.0, 5);
  const std::vector<float> c = NoisyDepth(view, model, 0.3, 8.0, 6);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  double sum = 0, sum2 = 0;
  for (float z : a) {
    sum += z - 4.0;
    sum2 += (z - 4.0) * (z - 4.0);
  }
  const double sd = std::sqrt(sum2 / a.size());
  EXPECT_NEAR(sum / a.size(), 0.0, 0.002);
  EXPECT_NEAR(sd, model.Sigma(4.0), 0.05 * model.Sigma(4.0));
}

TEST(SimDepthCameraTest, RgbUsesSurfaceColours) {
  World world = testing::OpenWorld();
  world.obstacles.push_back(Obstacle{"wall", Rgb{0, 0, 250}, Box(3.5, 0, 1.0, 20.0, 6.0)});
  const Scene scene = Scene::Build(world);
  CameraIntrinsics k;
  const RenderedView view = RenderView(scene, k, CameraPoseInWorld({0, 0, 1.5}, 0, 0), 0.3, 8.0);
  const cv::Mat rgb = RenderRgb(view, scene);
  ASSERT_EQ(rgb.type(), CV_8UC3);
  const cv::Vec3b centre = rgb.at<cv::Vec3b>(240, 320);  // BGR
  EXPECT_EQ(centre[1], 0);
  EXPECT_EQ(centre[2], 0);
  EXPECT_GT(centre[0], 100);
}

}  // namespace
}  // namespace semnav::sim
