// l_i of SPL: the planning service's A* on the world's ground-truth occupancy grid, from the
// start to the point of the target's success region (SuccessRegion: geodesic distance to a
// footprint within the success radius) that is nearest by path.
#pragma once

#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "clients/sim/core/episode_metrics.h"
#include "clients/sim/core/nearest_goal_search.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/world.h"
#include "semnav/common/v1/grid.pb.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"

namespace semnav::sim::loop {

// The point of `region` nearest by path on `grid` (the grid the region was built on); nullopt
// when none is reachable from `start`.
std::optional<NearestGoal> NearestSuccessPoint(const SuccessRegion& region,
                                               const GroundTruthGrid& grid,
                                               const Eigen::Vector2d& start);
// The same for the success region of `label` with `success_radius`, built on `grid`.
std::optional<NearestGoal> NearestSuccessPoint(const World& world, const GroundTruthGrid& grid,
                                               const Eigen::Vector2d& start,
                                               const std::string& label, double success_radius);

// The rasterized world as a GridMap with one OCCUPANCY layer (0 free, 100 occupied).
semnav::common::v1::GridMap ToGridMap(const GroundTruthGrid& grid);

// NOT_FOUND when no point of `region` (built on `grid`) can be reached; planning errors pass
// through.
absl::StatusOr<double> ShortestPathToTarget(semnav::planning::v1::PlanningService::Stub& planning,
                                            const SuccessRegion& region,
                                            const GroundTruthGrid& grid,
                                            const Eigen::Vector2d& start);

}  // namespace semnav::sim::loop
