#include "services/reasoning/core/input_limits.h"

#include <cmath>
#include <string>

#include "gtest/gtest.h"
#include "services/common/status/field_error.h"

namespace semnav::reasoning {
namespace {

std::string Repeat(const std::string& unit, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += unit;
  return out;
}

TEST(GatewayInputLimitsTest, InstructionsAreCountedInCharactersNotBytes) {
  EXPECT_EQ(Utf8Chars("去厨房找红色杯子"), 8u);  // 24 bytes
  // 1000 Chinese characters are 3000 bytes and allowed; one more is not.
  EXPECT_TRUE(CheckInstruction(Repeat("杯", 1000), "instruction").ok());
  absl::Status refused = CheckInstruction(Repeat("杯", 1001), "instruction");
  EXPECT_EQ(refused.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(refused), "instruction");
  EXPECT_LT(refused.message().size(), 200u);
}

TEST(GatewayInputLimitsTest, PoseAndSearchAreaNameTheCoordinate) {
  RobotPose pose;
  pose.position = Eigen::Vector3d(0, std::nan(""), 0);
  EXPECT_EQ(ErrorField(CheckRobotPose(pose, "state.pose.position")), "state.pose.position.y");
  pose.position = Eigen::Vector3d(0, 0, 2 * kMaxCoordinateM);
  EXPECT_EQ(ErrorField(CheckRobotPose(pose, "state.pose.position")), "state.pose.position.z");
  pose.position = Eigen::Vector3d(kMaxCoordinateM, -kMaxCoordinateM, 0);
  EXPECT_TRUE(CheckRobotPose(pose, "state.pose.position").ok());

  SearchArea area{Eigen::Vector2d(0, 0), Eigen::Vector2d(INFINITY, 5)};
  EXPECT_EQ(ErrorField(CheckSearchArea(area, "search_area")), "search_area.max_x");
  area.max = Eigen::Vector2d(5, 0);  // max_y == min_y: empty
  EXPECT_EQ(ErrorField(CheckSearchArea(area, "search_area")), "search_area");
  area.max = Eigen::Vector2d(5, 5);
  EXPECT_TRUE(CheckSearchArea(area, "search_area").ok());
}

TEST(GatewayInputLimitsTest, TargetSpecLimits) {
  TargetSpec target;
  target.name = "cup";
  target.colours = {"red", std::string(kMaxIdBytes + 1, 'x')};
  EXPECT_EQ(ErrorField(CheckTargetSpec(target, "target")), "target.colours[1]");
  target.colours.assign(kMaxTargetColours + 1, "red");
  EXPECT_EQ(ErrorField(CheckTargetSpec(target, "target")), "target.colours");
  target.colours = {"red"};
  target.anchor = std::string(1 << 20, 'a');
  absl::Status refused = CheckTargetSpec(target, "target");
  EXPECT_EQ(ErrorField(refused), "target.anchor");
  EXPECT_LT(refused.message().size(), 200u);  // a 1 MB value is not echoed
}

TEST(GatewayInputLimitsTest, CommandsCarryOnlyFiniteSaneNumbers) {
  RobotCommand navigate;
  navigate.kind = CommandKind::kNavigate;
  navigate.goal = Eigen::Vector3d(1, 2, 0);
  navigate.path = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 0)};
  EXPECT_TRUE(CheckCommand(navigate).ok());
  navigate.goal_yaw = std::nan("");
  EXPECT_EQ(ErrorField(CheckCommand(navigate)), "goal_yaw");
  navigate.goal_yaw = 0.0;
  navigate.max_speed = -1.0;
  EXPECT_EQ(ErrorField(CheckCommand(navigate)), "max_speed_mps");
  navigate.max_speed = 0.15;
  navigate.path[0].x() = 1e9;
  EXPECT_EQ(ErrorField(CheckCommand(navigate)), "path[0].x");

  RobotCommand rotate;
  rotate.kind = CommandKind::kRotate;
  rotate.angular_speed = 0.5;
  rotate.duration_s = 12.0;
  EXPECT_TRUE(CheckCommand(rotate).ok());
  rotate.angular_speed = INFINITY;
  EXPECT_EQ(ErrorField(CheckCommand(rotate)), "angular_speed_rps");
  // A camera tilt is in [0, pi/2], on a rotation and on a hold alike.
  rotate.angular_speed = 0.5;
  RobotCommand hold;
  hold.kind = CommandKind::kHold;
  hold.duration_s = 2.0;
  for (RobotCommand* command : {&rotate, &hold}) {
    command->camera_tilt_rad = 0.5;
    EXPECT_TRUE(CheckCommand(*command).ok());
    for (double tilt : {static_cast<double>(NAN), -0.1, 1.6}) {
      command->camera_tilt_rad = tilt;
      EXPECT_EQ(ErrorField(CheckCommand(*command)), "camera_tilt_rad");
    }
  }
}

}  // namespace
}  // namespace semnav::reasoning
