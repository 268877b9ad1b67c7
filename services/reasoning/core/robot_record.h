// What the gateway knows of one robot, as plain values (issue 18, item 5): its pose, its clock,
// its mobility, its active task, its emergency stop, its topological memory and the command
// ids of its session. The server's hub adds what is transport (the session stream, the last
// state and command as sent, simulated-step inputs).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "services/reasoning/core/robot_types.h"
#include "services/reasoning/core/topological_memory.h"

namespace semnav::reasoning {

struct RobotRecord {
  bool simulated_clock = false;          // the session declared a simulated clock
  double sim_now_s = 0.0;                // stamp of the last state (simulated clock)
  uint64_t synced_mapping_revision = 0;  // frames the scene graph was brought up to
  RobotPose pose;
  bool fly_roll = false;             // the latest hello offered the fly-roll mode
  double footprint_radius_m = 0.0;   // the latest hello's footprint
  double camera_tilt_max_rad = 0.0;  // the latest hello's camera tilt (0 = cannot tilt)
  RobotPlatform platform = RobotPlatform::kUnspecified;  // from the latest hello's modes
  bool emergency_stop = false;
  std::string active_task;  // "" = none
  std::unique_ptr<TopologicalMemory> memory;
  uint64_t next_command_id = 1;
  uint64_t last_session_command = 0;   // id sent on the session
  uint64_t last_executor_command = 0;  // the executor's id for it
};

}  // namespace semnav::reasoning
