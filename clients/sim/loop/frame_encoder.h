// A simulator capture as mapping's SensorFrame: depth in metres, intrinsics, the camera pose the
// robot believes (odometry), and the detections (boxes + embeddings; no ground truth).
#pragma once

#include <string>

#include "clients/sim/core/sensor_frame.h"
#include "semnav/mapping/v1/frames.pb.h"

namespace semnav::sim::loop {

semnav::mapping::v1::SensorFrame EncodeFrame(const SensorFrame& frame, const std::string& robot_id);

}  // namespace semnav::sim::loop
