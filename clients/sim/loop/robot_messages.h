// Messages the simulated robot sends on its gateway session: hello, state and command feedback.
#pragma once

#include <string>

#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/sim_robot.h"
#include "clients/sim/loop/command_executor.h"
#include "semnav/reasoning/v1/robot_session.pb.h"

namespace semnav::sim::loop {

// Capabilities of a robot of `modality` with `robot`'s speeds and footprint.
semnav::reasoning::v1::SessionHello Hello(const std::string& robot_id, Modality modality, const RobotConfig& robot);
// The robot's odometry pose and locomotion mode at its simulated time.
semnav::reasoning::v1::ConnectRequest StateMessage(const SimRobot& robot, const std::string& robot_id);
semnav::reasoning::v1::ConnectRequest FeedbackMessage(const Feedback& feedback);

}  // namespace semnav::sim::loop
