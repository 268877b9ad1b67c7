// l_i of SPL: the planning service's A* on the world's ground-truth occupancy grid, from the
// start to the point within the success radius of any target instance that is nearest by path.
#pragma once

#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "clients/sim/core/nearest_goal_search.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/world.h"
#include "semnav/common/v1/grid.pb.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"

namespace semnav::sim::loop {

// The point of the success region (within `success_radius` of an instance of `label`) nearest
// by path on `grid`; nullopt when none is reachable from `start`.
std::optional<NearestGoal> NearestSuccessPoint(const World& world, const GroundTruthGrid& grid,
                                               const Eigen::Vector2d& start, const std::string& label,
                                               double success_radius);

// The rasterized world as a GridMap with one OCCUPANCY layer (0 free, 100 occupied).
semnav::common::v1::GridMap ToGridMap(const GroundTruthGrid& grid);

// NOT_FOUND when no instance of `label` can be reached; planning errors pass through.
absl::StatusOr<double> ShortestPathToTarget(semnav::planning::v1::PlanningService::Stub& planning,
                                            const World& world, const GroundTruthGrid& grid,
                                            const Eigen::Vector2d& start, const std::string& label,
                                            double success_radius);

}  // namespace semnav::sim::loop
