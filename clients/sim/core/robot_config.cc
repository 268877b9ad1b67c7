#include "clients/sim/core/robot_config.h"

namespace semnav::sim {

RobotConfig RobotConfig::ForModality(Modality modality) {
  RobotConfig config;
  switch (modality) {
    case Modality::kGround:
      config.camera_tilt_max = 0.6;
      break;
    case Modality::kUav:
      config.radius = 0.3;
      config.body_height = 0.3;
      config.ground_clearance = 0.0;
      config.yaw_rate = 2.0;
      config.camera_height = 0.1;
      config.camera_pitch = 0.3;
      break;
    case Modality::kFlyRoll:
      config.radius = 0.2;
      config.body_height = 0.4;
      config.ground_clearance = 0.05;
      config.camera_height = 0.3;
      break;
  }
  return config;
}

}  // namespace semnav::sim
