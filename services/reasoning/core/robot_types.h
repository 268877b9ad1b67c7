// What the executor exchanges with a robot session: pose in, feedback in, commands out.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace semnav::reasoning {

struct RobotPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // map frame, metres
  double yaw = 0.0;                                    // rad, counter-clockwise from +x
};

// How the robot moves and sees, as planning's exploration reads it: a robot that can fly (UAV,
// fly-roll) has a wide view; a ground robot a short, level one.
enum class RobotPlatform { kUnspecified, kGround, kAerial };

enum class RobotFeedback { kGoalReached, kFailed, kBlocked };

enum class CommandKind { kNavigate, kRotate, kStop, kHold };

struct RobotCommand {
  CommandKind kind = CommandKind::kHold;
  uint64_t id = 0;                                 // feedback refers to this id
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();  // kNavigate: final position
  double goal_yaw = 0.0;                           // kNavigate: final heading, rad
  double max_speed = 0.0;                          // kNavigate: m/s, 0 = robot default
  std::vector<Eigen::Vector3d> path;               // kNavigate: planned waypoints incl. goal
  double angular_speed = 0.0;                      // kRotate: rad/s (positive = counter-clockwise)
  double duration_s = 0.0;       // kRotate / kHold: seconds, 0 = until next command
  double camera_tilt_rad = 0.0;  // kRotate / kHold: camera tilted up from the default view, rad
  std::string reason;            // shown to the operator
};

}  // namespace semnav::reasoning
