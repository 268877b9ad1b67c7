#pragma once

#include <cstdint>
#include <optional>

#include "absl/status/status.h"
#include "services/mapping/core/sensor_frame.h"

namespace semnav::mapping {

// What validation needs to know about the map's current state.
struct ValidationContext {
  // Last accepted stamp of this frame's robot, if any.
  std::optional<int64_t> last_stamp_ns;
  // Embedding length already used by the map (0: none seen yet, any length accepted).
  int embedding_dim = 0;
};

// Checks a frame before anything is changed. INVALID_ARGUMENT names the offending field
// (e.g. "depth.width", "pose.orientation", "detections[2].box"); a stamp older than the
// robot's last one is FAILED_PRECONDITION on "stamp".
absl::Status ValidateFrame(const SensorFrame& frame, const ValidationContext& context);

}  // namespace semnav::mapping
