#include "clients/sim/core/sim_robot.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/depth_noise.h"
#include "clients/sim/core/rgb_image.h"
#include "clients/sim/core/view_renderer.h"
#include "services/common/status/field_error.h"

namespace semnav::sim {
namespace {

constexpr double kEpsilon = 1e-9;

// Distinct random streams per frame and purpose, all derived from the episode seed.
enum class Stream : uint64_t { kOdometry = 1, kDepth = 2, kDetections = 3 };

uint64_t StreamSeed(uint64_t seed, Stream stream, uint64_t frame) {
  return MixSeed(MixSeed(seed, static_cast<uint64_t>(stream)), frame);
}

}  // namespace

SimRobot::SimRobot(const World& world, const Scene& scene, const StartPose& start,
                   const RobotConfig& robot, const SensorConfig& sensors, uint64_t seed)
    : world_(world),
      scene_(scene),
      modality_(start.modality),
      robot_(robot),
      sensors_(sensors),
      seed_(seed),
      pose_{start.position, start.yaw},
      odometry_(pose_, sensors.odometry, StreamSeed(seed, Stream::kOdometry, 0)) {}

absl::Status SimRobot::Apply(const RobotCommand& command) {
  if (stopped_)
    return FieldStatus(absl::StatusCode::kFailedPrecondition, "robot", "episode already stopped");
  if (const auto* follow = std::get_if<FollowPath>(&command)) {
    if (follow->waypoints.empty()) {
      return InvalidField("follow_path.waypoints", "empty path");
    }
    std::deque<Waypoint> path;
    for (size_t i = 0; i < follow->waypoints.size(); ++i) {
      Waypoint w = follow->waypoints[i];
      if (modality_ == Modality::kGround && w.mode == MotionMode::kFly) {
        return InvalidField(absl::StrCat("follow_path.waypoints[", i, "].mode"),
                            "a ground robot cannot fly");
      }
      if (modality_ == Modality::kUav) w.mode = MotionMode::kFly;
      if (w.mode == MotionMode::kRoll) w.position.z() = 0.0;
      path.push_back(w);
    }
    path_ = std::move(path);
    turn_target_.reset();
  } else if (const auto* rotate = std::get_if<Rotate>(&command)) {
    path_.clear();
    turn_target_ = WrapAngle(rotate->yaw);
  } else if (std::holds_alternative<Hold>(command)) {
    path_.clear();
    turn_target_.reset();
  } else {
    path_.clear();
    turn_target_.reset();
    stopped_ = true;
  }
  return absl::OkStatus();
}

std::optional<int> SimRobot::Touching(const Eigen::Vector3d& base) const {
  return scene_.SolidTouchingCylinder(base.head<2>(), robot_.radius,
                                      base.z() + robot_.ground_clearance,
                                      base.z() + robot_.body_height);
}

double SimRobot::Turn(double target_yaw, double budget) {
  const Pose before = pose_;
  const double error = WrapAngle(target_yaw - pose_.yaw);
  const double max_turn = robot_.yaw_rate * budget;
  const double turn = std::clamp(error, -max_turn, max_turn);
  pose_.yaw = WrapAngle(pose_.yaw + turn);
  odometry_.Update(before, pose_);
  return std::abs(turn) / robot_.yaw_rate;
}

double SimRobot::Advance(double budget, StepReport& report) {
  const Waypoint& target = path_.front();
  const Eigen::Vector3d delta = target.position - pose_.position;
  const Eigen::Vector2d horizontal = delta.head<2>();
  std::optional<double> steer_to;  // a heading reached while moving
  if (horizontal.norm() > kEpsilon) {
    const Eigen::Vector2d facing = target.reverse ? Eigen::Vector2d(-horizontal) : horizontal;
    const double heading = std::atan2(facing.y(), facing.x());
    const double error = std::abs(WrapAngle(heading - pose_.yaw));
    const double in_place = error - std::max(robot_.turn_while_moving_max_rad, 0.0);
    if (error > robot_.heading_tolerance && in_place > kEpsilon) {
      // In place until the rest of the turn can be made on the move.
      report.activity = RobotActivity::kTurning;
      return std::max(Turn(heading, std::min(budget, in_place / robot_.yaw_rate)), kEpsilon);
    }
    if (error > robot_.heading_tolerance) steer_to = heading;
  }
  report.activity = RobotActivity::kMoving;
  // Take-off and landing are flown even when the segment ends on the ground.
  const bool flying = target.mode == MotionMode::kFly || pose_.position.z() > kEpsilon ||
                      target.position.z() > kEpsilon;
  const double speed = flying ? robot_.fly_speed : robot_.roll_speed;
  const double distance = delta.norm();
  const double travel = std::min(distance, speed * budget);
  // Move in small increments so thin walls cannot be skipped; halt before touching.
  const int steps = std::max(1, static_cast<int>(std::ceil(travel / robot_.collision_step)));
  const Eigen::Vector3d from = pose_.position;
  double moved = 0.0;
  for (int i = 1; i <= steps; ++i) {
    const double along = travel * i / steps;
    const Eigen::Vector3d next =
        distance > kEpsilon ? Eigen::Vector3d(from + delta * (along / distance)) : target.position;
    if (const std::optional<int> solid = Touching(next)) {
      const SceneSolid& s = scene_.solids()[*solid];
      report.collision = CollisionEvent{time_s_, pose_.position, s.kind, s.object_index};
      collisions_.push_back(*report.collision);
      path_.clear();
      report.activity = RobotActivity::kIdle;
      return budget;  // the rest of the step is spent blocked
    }
    const Pose before = pose_;
    (flying ? fly_m_ : roll_m_) += (next - pose_.position).norm();
    pose_.position = next;
    odometry_.Update(before, pose_);
    moved = along;
  }
  if (steer_to) Turn(*steer_to, moved / speed);
  if (moved >= distance - kEpsilon) {
    path_.pop_front();
    if (path_.empty()) report.arrived = true;
  }
  return std::max(moved / speed, kEpsilon);
}

StepReport SimRobot::Step(double dt) {
  StepReport report;
  double left = dt;
  while (left > kEpsilon && !stopped_) {
    if (turn_target_) {
      report.activity = RobotActivity::kTurning;
      left -= Turn(*turn_target_, left);
      if (std::abs(WrapAngle(*turn_target_ - pose_.yaw)) < kEpsilon) turn_target_.reset();
      if (turn_target_) break;
    } else if (!path_.empty()) {
      left -= Advance(left, report);
      if (report.collision) break;
    } else {
      break;
    }
  }
  if (stopped_) report.activity = RobotActivity::kStopped;
  time_s_ += dt;
  return report;
}

void SimRobot::Kidnap(const Pose& to) {
  pose_ = Pose{to.position, WrapAngle(to.yaw)};
  path_.clear();
  turn_target_.reset();
}

absl::Status SimRobot::SetCameraTilt(double tilt_rad) {
  if (!(tilt_rad >= 0.0 && tilt_rad <= robot_.camera_tilt_max + 1e-12)) {
    return absl::InvalidArgumentError(absl::StrCat("camera_tilt_rad ", tilt_rad, " is outside [0, ",
                                                   robot_.camera_tilt_max,
                                                   "] (the camera's tilt range)"));
  }
  camera_tilt_ = tilt_rad;
  return absl::OkStatus();
}

SensorFrame SimRobot::Capture() {
  SensorFrame frame;
  frame.index = frame_index_++;
  frame.time_s = time_s_;
  frame.true_pose = pose_;
  frame.odometry_pose = odometry_.pose();
  const Eigen::Vector3d up(0.0, 0.0, robot_.camera_height);
  const double pitch = robot_.camera_pitch - camera_tilt_;
  frame.world_from_camera = CameraPoseInWorld(pose_.position + up, pose_.yaw, pitch);
  frame.odom_from_camera =
      CameraPoseInWorld(odometry_.pose().position + up, odometry_.pose().yaw, pitch);
  frame.intrinsics = sensors_.intrinsics;
  const RenderedView view = RenderView(scene_, sensors_.intrinsics, frame.world_from_camera,
                                       sensors_.min_range, sensors_.max_range);
  frame.depth = sensors_.depth_noise
                    ? NoisyDepth(view, sensors_.noise, sensors_.min_range, sensors_.max_range,
                                 StreamSeed(seed_, Stream::kDepth, frame.index))
                    : view.depth;
  if (sensors_.rgb) frame.rgb = RenderRgb(view, scene_);
  if (sensors_.detections) {
    frame.detections = DetectObjects(view, scene_, world_, sensors_.detector,
                                     StreamSeed(seed_, Stream::kDetections, frame.index));
    frame.detector_ran = true;
  }
  return frame;
}

}  // namespace semnav::sim
