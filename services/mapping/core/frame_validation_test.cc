#include "services/mapping/core/frame_validation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "services/mapping/testing/synthetic_room.h"

namespace semnav::mapping {
namespace {

using ::testing::HasSubstr;

SensorFrame GoodFrame() {
  const testing::SyntheticRoom room = testing::StandardRoom();
  SensorFrame frame = testing::RenderFrame(room, testing::RoomTour(room, 1)[0], 1000);
  Detection det;
  det.label = "chair";
  det.score = 0.9;
  det.box = {10, 10, 50, 60};
  det.embedding = {1.0f, 0.0f, 0.0f};
  frame.detections.push_back(det);
  return frame;
}

void ExpectInvalid(const SensorFrame& frame, absl::string_view field,
                   const ValidationContext& context = {}) {
  const absl::Status status = ValidateFrame(frame, context);
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << status;
  EXPECT_THAT(std::string(status.message()), HasSubstr(std::string(field)));
}

TEST(FrameValidationTest, AcceptsGoodFrame) { EXPECT_TRUE(ValidateFrame(GoodFrame(), {}).ok()); }

TEST(FrameValidationTest, RejectsDepthSizeDifferentFromIntrinsics) {
  SensorFrame frame = GoodFrame();
  frame.intrinsics.width = 320;
  ExpectInvalid(frame, "depth.width");
}

TEST(FrameValidationTest, RejectsUnknownEncodingAndShortData) {
  SensorFrame frame = GoodFrame();
  frame.depth.encoding = DepthEncoding::kUnknown;
  ExpectInvalid(frame, "depth.encoding");
  frame = GoodFrame();
  frame.depth.data.resize(10);
  ExpectInvalid(frame, "depth.data");
}

TEST(FrameValidationTest, RejectsNonFiniteOrNonUnitPose) {
  SensorFrame frame = GoodFrame();
  frame.pose.position.x() = std::nan("");
  ExpectInvalid(frame, "pose.position");
  frame = GoodFrame();
  frame.pose.orientation = Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0);
  ExpectInvalid(frame, "pose.orientation");
}

// Finite is not enough: a camera at 1e300 m created objects at 1e300 m.
TEST(FrameValidationTest, RejectsHugeOrNonFiniteNumbersNamingThePath) {
  SensorFrame frame = GoodFrame();
  frame.pose.position.y() = 1e300;
  ExpectInvalid(frame, "pose.position.y");
  frame = GoodFrame();
  frame.intrinsics.cx = 1e300;
  ExpectInvalid(frame, "intrinsics.cx");
  frame = GoodFrame();
  frame.detections[0].embedding[1] = std::numeric_limits<float>::quiet_NaN();
  ExpectInvalid(frame, "detections[0].embedding[1]");
  frame = GoodFrame();
  frame.lidar_points.emplace_back(1.0f, std::numeric_limits<float>::infinity(), 0.0f);
  ExpectInvalid(frame, "lidar_points[0].y");
}

TEST(FrameValidationTest, RejectsOversizedIdsWithoutEchoingThem) {
  SensorFrame frame = GoodFrame();
  frame.robot_id = std::string(1 << 20, 'r');
  const absl::Status status = ValidateFrame(frame, {});
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(status.message()), HasSubstr("robot_id"));
  EXPECT_LT(status.message().size(), 200u);
  frame = GoodFrame();
  frame.detections[0].label = std::string(1000, 'l');
  ExpectInvalid(frame, "detections[0].label");
}

TEST(FrameValidationTest, RejectsStampGoingBackwardsForThatRobot) {
  const absl::Status status = ValidateFrame(GoodFrame(), ValidationContext{1001, 0});
  EXPECT_EQ(status.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_THAT(std::string(status.message()), HasSubstr("stamp"));
  EXPECT_TRUE(ValidateFrame(GoodFrame(), ValidationContext{1000, 0}).ok());
}

TEST(FrameValidationTest, RejectsBoxOutsideImage) {
  SensorFrame frame = GoodFrame();
  frame.detections[0].box.x_max = 641;
  ExpectInvalid(frame, "detections[0].box");
}

TEST(FrameValidationTest, RejectsEmbeddingLengthMismatch) {
  ExpectInvalid(GoodFrame(), "detections[0].embedding", ValidationContext{std::nullopt, 512});
  SensorFrame frame = GoodFrame();
  frame.detections.push_back(frame.detections[0]);
  frame.detections[1].embedding.push_back(0.0f);
  ExpectInvalid(frame, "detections[1].embedding");
}

}  // namespace
}  // namespace semnav::mapping
