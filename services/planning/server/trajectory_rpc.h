#pragma once

#include <string>

#include "absl/status/status.h"
#include "semnav/common/v1/grid.pb.h"
#include "semnav/planning/v1/exploration.pb.h"
#include "services/planning/server/exploration_config.h"

namespace semnav::planning {

// SmoothTrajectory on a resolved grid (`field` names it in errors).
absl::Status SmoothTrajectoryOn(const semnav::common::v1::GridMap& grid, const std::string& field,
                                const semnav::planning::v1::SmoothTrajectoryRequest& request,
                                const TrajectoryConfig& config, int occupied_percent,
                                semnav::planning::v1::SmoothTrajectoryResponse* response);

}  // namespace semnav::planning
