#include "services/reasoning/core/inverse_mapping.h"

#include <cmath>

#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

PinholeCamera Camera() { return {400.0, 400.0, 320.0, 240.0, 640, 480}; }

EroiGrid LineGrid() {
  EroiGridSpec spec;
  spec.min = Eigen::Vector3d(0.0, -6.0, 0.0);
  spec.delta = 3.0;
  spec.nx = 5;
  spec.ny = 4;
  spec.nz = 1;
  return *EroiGrid::Create(spec);
}

TEST(GatewayInverseMappingTest, FixedRotationOfEquationFive) {
  // Forward (body x) becomes optical z, left (body y) becomes -x, up (body z) becomes -y.
  EXPECT_TRUE((BodyToOptical() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE((BodyToOptical() * Eigen::Vector3d::UnitY()).isApprox(-Eigen::Vector3d::UnitX()));
  EXPECT_TRUE((BodyToOptical() * Eigen::Vector3d::UnitZ()).isApprox(-Eigen::Vector3d::UnitY()));
  // A camera yawed +90 deg looks along world +y: a point 5 m along +y is straight ahead.
  const Eigen::Quaterniond yaw90(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(
      (WorldToOptical(yaw90) * Eigen::Vector3d(0, 5, 0)).isApprox(Eigen::Vector3d(0, 0, 5)));
}

TEST(GatewayInverseMappingTest, PinholeProjectionAndDistanceWindowByHand) {
  const EroiGrid grid = LineGrid();
  InverseMapper mapper(&grid, InverseMappingConfig{});
  // Camera at (0, 0, 1.5) looking along +x (identity orientation).
  std::vector<CodeLabel> labels =
      mapper.Project(Eigen::Vector3d(0, 0, 1.5), Eigen::Quaterniond::Identity(), Camera());
  bool found = false;
  for (const CodeLabel& label : labels) {
    EXPECT_GT(label.distance_m, 3.0);
    EXPECT_LT(label.distance_m, 12.0);
    if (label.code == "D3A") {  // centre (9, 0, 0): X = 0, Y = 1.5, Z = 9
      found = true;
      EXPECT_NEAR(label.pixel.x(), 320.0, 1e-9);
      EXPECT_NEAR(label.pixel.y(), 400.0 * 1.5 / 9.0 + 240.0, 1e-9);
      EXPECT_NEAR(label.distance_m, std::hypot(9.0, 1.5), 1e-9);
    }
  }
  EXPECT_TRUE(found);
  // (3, 0, 0) is only 3.35 m away but (0, *, *) is behind or beside the camera: never listed.
  for (const CodeLabel& label : labels) EXPECT_NE(label.world.x(), 0.0) << label.code;
}

TEST(GatewayInverseMappingTest, CullingKeepsTheFartherOfTwoOverlappingLabels) {
  auto label = [](const char* code, double distance, int x) {
    CodeLabel out;
    out.code = code;
    out.distance_m = distance;
    out.box = cv::Rect(x, 95, 30, 12);
    return out;
  };
  std::vector<CodeLabel> kept =
      InverseMapper::Cull({label("B3A", 4.0, 90), label("F3A", 10.0, 95), label("C1A", 6.0, 290)});
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].code, "F3A");
  EXPECT_EQ(kept[1].code, "C1A");
}

TEST(GatewayInverseMappingTest, DrawsTheCodesIntoTheImage) {
  const EroiGrid grid = LineGrid();
  InverseMapper mapper(&grid, InverseMappingConfig{});
  std::vector<CodeLabel> labels = InverseMapper::Cull(
      mapper.Project(Eigen::Vector3d(0, 0, 1.5), Eigen::Quaterniond::Identity(), Camera()));
  ASSERT_FALSE(labels.empty());
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(0, 128, 0));
  mapper.Draw(labels, image);
  const cv::Rect inside = labels.front().box & cv::Rect(0, 0, 640, 480);
  cv::Scalar mean = cv::mean(image(inside));
  EXPECT_NE(mean[1], 128.0);  // the green background was painted over by box and text
  EXPECT_GT(mean[0], 0.0);    // white text pixels inside the black box
}

}  // namespace
}  // namespace semnav::reasoning
