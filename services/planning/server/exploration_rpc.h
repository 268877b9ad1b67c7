#pragma once

#include <string>

#include "absl/status/status.h"
#include "semnav/common/v1/grid.pb.h"
#include "semnav/planning/v1/exploration.pb.h"
#include "services/planning/server/grid_conversion.h"
#include "services/planning/server/planning_config.h"

namespace semnav::planning {

// ExtractFrontiers on a resolved grid (`field` names it in errors).
absl::Status ExtractFrontiersOn(const semnav::common::v1::GridMap& grid, const std::string& field,
                                const semnav::planning::v1::ExtractFrontiersRequest& request,
                                const PlanningConfig& config,
                                semnav::planning::v1::ExtractFrontiersResponse* response);

// ScoreFrontiers: the seed 002 terms of caller-given frontiers under the
// request's weights (unset = config).
absl::Status ScoreFrontiersOn(const semnav::planning::v1::ScoreFrontiersRequest& request,
                              const PlanningConfig& config,
                              semnav::planning::v1::ScoreFrontiersResponse* response);

// SelectExplorationGoal on a resolved grid.
absl::Status SelectGoalOn(const semnav::common::v1::GridMap& grid, const std::string& field,
                          const semnav::planning::v1::SelectExplorationGoalRequest& request,
                          const PlanningConfig& config,
                          semnav::planning::v1::SelectExplorationGoalResponse* response);

}  // namespace semnav::planning
