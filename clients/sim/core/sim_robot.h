#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "clients/sim/core/odometry.h"
#include "clients/sim/core/robot_command.h"
#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/sensor_frame.h"
#include "clients/sim/core/world.h"

namespace semnav::sim {

enum class RobotActivity { kIdle, kTurning, kMoving, kStopped };

struct CollisionEvent {
  double time_s = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // where the robot halted
  std::string kind;       // kind of the solid touched ("wall", "object", ...)
  int object_index = -1;  // World::objects index when an object was touched
};

struct StepReport {
  RobotActivity activity = RobotActivity::kIdle;
  bool arrived = false;  // the last waypoint was reached during this step
  std::optional<CollisionEvent> collision;
};

// The simulated robot: apply a command, advance simulated time, capture a sensor frame.
// Everything is a function of (world, start, configs, seed, command sequence, step sizes).
class SimRobot {
 public:
  // `world` and `scene` (built from it) must outlive the robot.
  SimRobot(const World& world, const Scene& scene, const StartPose& start, const RobotConfig& robot,
           const SensorConfig& sensors, uint64_t seed);

  // INVALID_ARGUMENT for an empty path or a fly waypoint on a ground robot (names the
  // waypoint); FAILED_PRECONDITION after Stop. State is unchanged on error.
  absl::Status Apply(const RobotCommand& command);
  // Tilts the camera up from its default pitch (0 = the default view) for the frames captured
  // from now on. INVALID_ARGUMENT outside [0, RobotConfig::camera_tilt_max]; unchanged then.
  absl::Status SetCameraTilt(double tilt_rad);
  double camera_tilt() const { return camera_tilt_; }
  // Advances simulated time by dt seconds (dt > 0), moving and checking collisions.
  StepReport Step(double dt);
  // Renders the sensors at the current time; frame indices count up from 0.
  SensorFrame Capture();
  // "Kidnapped robot": carried to `to` at once, without telling it. Its odometry does not see the
  // move, and the motion it was executing ends (it was picked up).
  void Kidnap(const Pose& to);

  const Pose& pose() const { return pose_; }
  const Pose& odometry_pose() const { return odometry_.pose(); }
  double time_s() const { return time_s_; }
  double path_length_m() const { return roll_m_ + fly_m_; }
  double roll_distance_m() const { return roll_m_; }
  double fly_distance_m() const { return fly_m_; }
  double energy_j() const { return robot_.energy.Roll(roll_m_) + robot_.energy.Fly(fly_m_); }
  bool stopped() const { return stopped_; }
  const std::vector<CollisionEvent>& collisions() const { return collisions_; }
  Modality modality() const { return modality_; }

 private:
  std::optional<int> Touching(const Eigen::Vector3d& base) const;
  // Each returns the seconds it consumed of `budget`.
  double Turn(double target_yaw, double budget);
  double Advance(double budget, StepReport& report);

  const World& world_;
  const Scene& scene_;
  Modality modality_;
  RobotConfig robot_;
  SensorConfig sensors_;
  uint64_t seed_;
  Pose pose_;
  Odometry odometry_;
  std::deque<Waypoint> path_;
  std::optional<double> turn_target_;
  bool stopped_ = false;
  double camera_tilt_ = 0.0;  // rad up from robot_.camera_pitch
  double time_s_ = 0.0;
  double roll_m_ = 0.0;
  double fly_m_ = 0.0;
  uint64_t frame_index_ = 0;
  std::vector<CollisionEvent> collisions_;
};

}  // namespace semnav::sim
