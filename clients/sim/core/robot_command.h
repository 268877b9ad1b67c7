#pragma once

#include <Eigen/Core>
#include <variant>
#include <vector>

// Commands a controller (the gateway's robot session, via an adapter) gives the robot.
namespace semnav::sim {

enum class MotionMode { kRoll, kFly };

struct Waypoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world frame; z = base altitude
  // How the segment ending here is travelled; segments touching the air are always flown.
  MotionMode mode = MotionMode::kRoll;
  // Driven backwards, keeping the heading (a recovery back-up, as Nav2's BackUp behaviour).
  bool reverse = false;
};

// Drive through the waypoints in order at the modality's speed, turning in place first
// whenever the next waypoint lies off the heading. Replaces any current motion.
struct FollowPath {
  std::vector<Waypoint> waypoints;
};
// Turn in place to an absolute heading (radians).
struct Rotate {
  double yaw = 0.0;
};
// Stay where you are (cancels motion); time still passes.
struct Hold {};
// The agent declares it has reached the goal: the episode's stop action. Final.
struct Stop {};

using RobotCommand = std::variant<FollowPath, Rotate, Hold, Stop>;

}  // namespace semnav::sim
