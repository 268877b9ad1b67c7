// A simulator capture as mapping's SensorFrame: depth in metres, intrinsics, the camera pose the
// robot believes (odometry), and the detections (boxes + embeddings; no ground truth); and its
// colour image as the gateway session's CameraFrame.
#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "clients/sim/core/sensor_frame.h"
#include "semnav/mapping/v1/frames.pb.h"
#include "semnav/reasoning/v1/robot_session.pb.h"

namespace semnav::sim::loop {

semnav::mapping::v1::SensorFrame EncodeFrame(const SensorFrame& frame, const std::string& robot_id);

// The colour image (RGB8) for the gateway's robot session, as EROI search (seed 000) reads it:
// intrinsics and the camera *body* pose (x forward, y left, z up) the robot believes.
// FAILED_PRECONDITION when the frame has no colour image (SensorConfig::rgb off).
absl::StatusOr<semnav::reasoning::v1::ConnectRequest> EncodeCameraFrame(const SensorFrame& frame);

}  // namespace semnav::sim::loop
