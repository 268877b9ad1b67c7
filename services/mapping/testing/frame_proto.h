#pragma once

#include "semnav/mapping/v1/frames.pb.h"
#include "services/mapping/core/sensor_frame.h"

namespace semnav::mapping::testing {

// Core frame -> wire frame (depth, intrinsics, pose, header; not detections), for tests and tools
// that feed semnav-mapping with synthetic frames.
v1::SensorFrame FrameToProto(const SensorFrame& frame);

}  // namespace semnav::mapping::testing
