// Messages the simulated robot sends on its gateway session: hello, state and command feedback.
#pragma once

#include <string>

#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/sim_robot.h"
#include "clients/sim/loop/command_executor.h"
#include "semnav/reasoning/v1/robot_session.pb.h"

namespace semnav::sim::loop {

// Capabilities of a robot of `modality` with `robot`'s speeds and footprint.
semnav::reasoning::v1::SessionHello Hello(const std::string& robot_id, Modality modality,
                                          const RobotConfig& robot);
// The robot's odometry pose and locomotion mode at its simulated time.
semnav::reasoning::v1::ConnectRequest StateMessage(const SimRobot& robot,
                                                   const std::string& robot_id);
// The same for a simulated-clock (lock-step) session: the state ends `step`, and mapping has
// acknowledged the robot's frames up to `mapping_revision`.
semnav::reasoning::v1::ConnectRequest StepStateMessage(const SimRobot& robot,
                                                       const std::string& robot_id, uint64_t step,
                                                       uint64_t mapping_revision);
semnav::reasoning::v1::ConnectRequest FeedbackMessage(const Feedback& feedback);

}  // namespace semnav::sim::loop
