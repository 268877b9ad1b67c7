#include "clients/sim/loop/frame_encoder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "clients/sim/loop/instruction.h"

namespace semnav::sim::loop {
namespace {

SensorFrame SmallFrame() {
  SensorFrame frame;
  frame.time_s = 2.5;
  frame.intrinsics = CameraIntrinsics{4, 2, 2.0, 2.0, 1.5, 0.5};
  frame.depth = {1.0f, 2.0f, 0.0f, 3.5f, 1.0f, 1.0f, 1.0f, 8.0f};
  frame.odom_from_camera = Eigen::Isometry3d::Identity();
  frame.odom_from_camera.translate(Eigen::Vector3d(1.0, 2.0, 0.88));
  Detection chair;
  chair.label = "chair";
  chair.score = 0.9;
  chair.box = Eigen::Vector4i(1, 0, 3, 1);  // inclusive: the right half of the image
  chair.embedding = {0.6f, 0.8f};
  frame.detections.detections.push_back(chair);
  return frame;
}

TEST(SimLoopFrameEncoderTest, DepthPoseAndDetectionsFollowTheContract) {
  const semnav::mapping::v1::SensorFrame out = EncodeFrame(SmallFrame(), "r1");
  EXPECT_EQ(out.header().robot_id(), "r1");
  EXPECT_EQ(out.header().stamp().seconds(), 2);
  EXPECT_EQ(out.header().stamp().nanos(), 500000000);
  EXPECT_EQ(out.depth().encoding(), semnav::common::v1::IMAGE_ENCODING_DEPTH_32FC1_M);
  ASSERT_EQ(out.depth().data().size(), 8 * sizeof(float));
  float last = 0.0f;
  std::memcpy(&last, out.depth().data().data() + 7 * sizeof(float), sizeof(float));
  EXPECT_EQ(last, 8.0f);
  EXPECT_EQ(out.intrinsics().width(), 4u);
  EXPECT_DOUBLE_EQ(out.camera_pose().position().y(), 2.0);
  EXPECT_DOUBLE_EQ(out.camera_pose().orientation().w(), 1.0);
  ASSERT_EQ(out.detections_size(), 1);
  // Half-open in the contract: x in [1, 4), y in [0, 2).
  EXPECT_EQ(out.detections(0).box().x_min(), 1.0);
  EXPECT_EQ(out.detections(0).box().x_max(), 4.0);
  EXPECT_EQ(out.detections(0).box().y_max(), 2.0);
  EXPECT_EQ(out.detections(0).embedding_size(), 2);
}

TEST(SimLoopFrameEncoderTest, NoisyBoxesAreClampedIntoTheImage) {
  SensorFrame frame = SmallFrame();
  frame.detections.detections[0].box = Eigen::Vector4i(-3, -1, 9, 5);
  const semnav::mapping::v1::SensorFrame out = EncodeFrame(frame, "r1");
  EXPECT_EQ(out.detections(0).box().x_min(), 0.0);
  EXPECT_EQ(out.detections(0).box().y_min(), 0.0);
  EXPECT_EQ(out.detections(0).box().x_max(), 4.0);
  EXPECT_EQ(out.detections(0).box().y_max(), 2.0);
}

TEST(SimLoopFrameEncoderTest, CameraFrameIsRgbWithTheBodyPose) {
  SensorFrame frame = SmallFrame();
  EXPECT_EQ(EncodeCameraFrame(frame).status().code(),
            absl::StatusCode::kFailedPrecondition);           // no colour
  frame.rgb = cv::Mat(2, 4, CV_8UC3, cv::Scalar(255, 0, 0));  // BGR: blue
  // A level optical frame looking along map +y: optical x (right) = +x, y (down) = -z, z = +y.
  Eigen::Matrix3d map_from_optical;
  map_from_optical << 1, 0, 0,  //
      0, 0, 1,                  //
      0, -1, 0;
  frame.odom_from_camera.linear() = map_from_optical;
  const absl::StatusOr<semnav::reasoning::v1::ConnectRequest> out = EncodeCameraFrame(frame);
  ASSERT_TRUE(out.ok()) << out.status();
  const semnav::reasoning::v1::CameraFrame& camera = out->camera();
  EXPECT_EQ(camera.image().encoding(), semnav::common::v1::IMAGE_ENCODING_RGB8);
  ASSERT_EQ(camera.image().data().size(), 4u * 2u * 3u);
  EXPECT_EQ(static_cast<uint8_t>(camera.image().data()[0]), 0);    // R
  EXPECT_EQ(static_cast<uint8_t>(camera.image().data()[2]), 255);  // B
  EXPECT_EQ(camera.intrinsics().width(), 4u);
  EXPECT_DOUBLE_EQ(camera.intrinsics().fx(), 2.0);
  EXPECT_DOUBLE_EQ(camera.camera_pose().position().z(), 0.88);
  // Body x forward = map +y: a 90 degree yaw, (w, z) = (cos 45, sin 45).
  EXPECT_NEAR(camera.camera_pose().orientation().w(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(camera.camera_pose().orientation().z(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(camera.camera_pose().orientation().x(), 0.0, 1e-12);
  EXPECT_NEAR(camera.camera_pose().orientation().y(), 0.0, 1e-12);
}

TEST(SimLoopInstructionTest, LanguageFollowsTheTargetName) {
  EXPECT_EQ(SearchInstruction("chair"), "find a chair");
  EXPECT_EQ(SearchInstruction("椅子"), "找椅子");
}

}  // namespace
}  // namespace semnav::sim::loop
