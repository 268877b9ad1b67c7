#pragma once

#include <cstdint>
#include <vector>

#include "semnav/mapping/v1/frames.pb.h"
#include "services/mapping/core/sensor_frame.h"

namespace semnav::mapping::testing {

// Core frame -> wire frame (depth, intrinsics, pose, header; not detections), for tests and tools
// that feed semnav-mapping with synthetic frames.
v1::SensorFrame FrameToProto(const SensorFrame& frame);

// A StandardRoom() frame from (0.5, 2, 1.2) looking at (4, 2, 0) at `stamp_ns`, with one "table"
// detection (score 0.9, an 80 px box) round the static box's centre (3.2, 1.3, 0.7), carrying
// `embedding`.
v1::SensorFrame StandardRoomFrameWithTable(int64_t stamp_ns, const std::vector<float>& embedding);

}  // namespace semnav::mapping::testing
