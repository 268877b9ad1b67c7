#include "clients/sim/loop/robot_messages.h"

#include "clients/sim/loop/proto_geometry.h"

namespace semnav::sim::loop {

namespace api = semnav::reasoning::v1;

api::SessionHello Hello(const std::string& robot_id, Modality modality, const RobotConfig& robot) {
  api::SessionHello hello;
  hello.set_robot_id(robot_id);
  hello.set_software_version("semnav-sim-loop");
  api::Capabilities* caps = hello.mutable_capabilities();
  switch (modality) {
    case Modality::kGround:
      caps->add_modes(api::LOCOMOTION_MODE_GROUND);
      caps->set_max_linear_speed_mps(robot.roll_speed);
      break;
    case Modality::kUav:
      caps->add_modes(api::LOCOMOTION_MODE_AIR);
      caps->set_max_linear_speed_mps(robot.fly_speed);
      caps->set_max_vertical_speed_mps(robot.fly_speed);
      break;
    case Modality::kFlyRoll:
      caps->add_modes(api::LOCOMOTION_MODE_FLY_ROLL);
      caps->set_max_linear_speed_mps(robot.fly_speed);
      caps->set_max_vertical_speed_mps(robot.fly_speed);
      break;
  }
  caps->set_max_angular_speed_rps(robot.yaw_rate);
  caps->set_footprint_radius_m(robot.radius);
  caps->set_camera_tilt_max_rad(robot.camera_tilt_max);
  return hello;
}

api::ConnectRequest StateMessage(const SimRobot& robot, const std::string& robot_id) {
  api::ConnectRequest request;
  api::RobotState* state = request.mutable_state();
  *state->mutable_header()->mutable_stamp() = ToStamp(robot.time_s());
  state->mutable_header()->set_frame_id("map");
  state->mutable_header()->set_robot_id(robot_id);
  *state->mutable_pose() = ToProtoPose(robot.odometry_pose());
  state->set_mode(robot.pose().position.z() > 0.05 ? api::LOCOMOTION_MODE_AIR
                                                   : api::LOCOMOTION_MODE_GROUND);
  state->set_battery_fraction(-1.0);
  return request;
}

api::ConnectRequest StepStateMessage(const SimRobot& robot, const std::string& robot_id,
                                     uint64_t step, uint64_t mapping_revision) {
  api::ConnectRequest request = StateMessage(robot, robot_id);
  request.mutable_state()->set_step(step);
  request.mutable_state()->set_mapping_revision(mapping_revision);
  return request;
}

api::ConnectRequest FeedbackMessage(const Feedback& feedback) {
  api::ConnectRequest request;
  request.mutable_feedback()->set_command_id(feedback.command_id);
  request.mutable_feedback()->set_kind(feedback.kind);
  request.mutable_feedback()->set_detail(feedback.detail);
  return request;
}

}  // namespace semnav::sim::loop
