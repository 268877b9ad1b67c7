#pragma once

#include "clients/sim/core/camera_model.h"
#include "clients/sim/core/depth_noise.h"
#include "clients/sim/core/detector.h"
#include "clients/sim/core/odometry.h"
#include "clients/sim/core/world.h"
#include "services/planning/core/energy_model.h"

namespace semnav::sim {

// Body and motion limits. The body is an upright cylinder from base + ground_clearance to
// base + body_height; position.z is the base altitude (0 for a robot on the floor).
struct RobotConfig {
  double radius = 0.25;
  double body_height = 0.6;
  double ground_clearance = 0.05;   // flat things lower than this (rugs, roads) are driven over
  double roll_speed = 0.5;          // m/s on the ground
  double fly_speed = 1.0;           // m/s in the air (seed 000 and 003: 1 m/s)
  double yaw_rate = 1.0;            // rad/s
  double heading_tolerance = 0.05;  // rad: heading errors below this are not corrected
  // Heading errors up to this are corrected while moving along the segment (a quadruped, a
  // multirotor and a thrust-rolled sphere translate in any direction); a larger one is turned
  // in place down to it first, as Nav2's regulated pure pursuit rotates to heading above its
  // rotate_to_heading_min_angle (0.785 rad). 0 = turn in place at every bend (Habitat's agent,
  // seed 004): at 0.785 the search found no more targets on the ground and fewer from the UAV,
  // whose camera no longer swept the scene at each bend (docs/performance/mission.md).
  double turn_while_moving_max_rad = 0.0;
  double camera_height = 0.88;  // above the base (the Habitat agent's camera height)
  double camera_pitch = 0.0;    // rad, positive looks down
  // How far the camera tilts up from camera_pitch on command (RotateAction.camera_tilt_rad, a
  // pan-tilt head), rad; 0 = fixed. Ground robots: 0.6, over Habitat's 30 deg LOOK_UP.
  double camera_tilt_max = 0.0;
  double collision_step = 0.05;  // m between collision checks along a motion
  planning::EnergyModel energy;  // seed 003: 400 J/m rolling, 800 J/m flying

  // Defaults per modality: ground robot; UAV (seed 000 limits: 1 m/s, 2 rad/s; camera
  // pitched 0.3 rad down); fly-roll sphere (seed 003: 330 mm frame, 1 m/s flight).
  static RobotConfig ForModality(Modality modality);
};

struct SensorConfig {
  CameraIntrinsics intrinsics;
  double min_range = 0.3;  // metres of z-depth
  double max_range = 8.0;
  bool depth_noise = true;
  DepthNoiseModel noise;
  bool rgb = false;  // render the flat-shaded colour image
  bool detections = true;
  DetectorConfig detector;
  OdometryDriftConfig odometry;
};

}  // namespace semnav::sim
