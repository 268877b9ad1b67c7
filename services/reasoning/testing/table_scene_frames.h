// Synthetic sensor frames for semnav-mapping showing the standard test room with a "table"
// detection, and a helper that streams them; shared by the gateway's end-to-end contract test
// and benchmark.
#pragma once

#include <grpcpp/channel.h>

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>

#include "absl/status/status.h"
#include "semnav/mapping/v1/frames.pb.h"

namespace semnav::reasoning::testing {

// Centre of the standard room's table-height box, map frame, metres.
inline const Eigen::Vector3d kTableCentre(3.2, 1.3, 0.7);

// The standard room seen from the fixed viewpoint, with one detection `label` boxed round the
// pixel of `point` (map frame; mapping places the object where the depth there says).
mapping::v1::SensorFrame LabelledFrame(int64_t stamp_ns, const std::string& label,
                                       const Eigen::Vector3d& point);
inline mapping::v1::SensorFrame TableFrame(int64_t stamp_ns) {
  return LabelledFrame(stamp_ns, "table", kTableCentre);
}

// Streams `count` labelled frames with stamps first_index * 100 ms, ... to mapping; fails on any
// rejected frame.
absl::Status StreamLabelledFrames(const std::shared_ptr<grpc::Channel>& mapping,
                                  int64_t first_index, int count, const std::string& label,
                                  const Eigen::Vector3d& point);
inline absl::Status StreamTableFrames(const std::shared_ptr<grpc::Channel>& mapping,
                                      int64_t first_index, int count) {
  return StreamLabelledFrames(mapping, first_index, count, "table", kTableCentre);
}

}  // namespace semnav::reasoning::testing
