#include "clients/sim/loop/shortest_path.h"

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <optional>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/episode_metrics.h"

namespace semnav::sim::loop {

namespace common = semnav::common::v1;
namespace planning = semnav::planning::v1;

common::GridMap ToGridMap(const GroundTruthGrid& grid) {
  common::GridMap out;
  out.set_resolution(grid.resolution);
  out.mutable_origin()->set_x(grid.origin.x());
  out.mutable_origin()->set_y(grid.origin.y());
  out.set_width(grid.width);
  out.set_height(grid.height);
  common::GridLayer* layer = out.add_layers();
  layer->set_kind(common::GRID_LAYER_KIND_OCCUPANCY);
  layer->set_data(std::string(grid.cells.begin(), grid.cells.end()));
  return out;
}

std::optional<NearestGoal> NearestSuccessPoint(const SuccessRegion& region,
                                               const GroundTruthGrid& grid,
                                               const Eigen::Vector2d& start) {
  if (region.empty()) return std::nullopt;
  return NearestReachableGoal(grid, start,
                              [&](const Eigen::Vector2d& p) { return region.Contains(p); });
}

std::optional<NearestGoal> NearestSuccessPoint(const World& world, const GroundTruthGrid& grid,
                                               const Eigen::Vector2d& start,
                                               const std::string& label, double success_radius) {
  return NearestSuccessPoint(SuccessRegion::Build(world, label, grid, success_radius), grid, start);
}

absl::StatusOr<double> ShortestPathToTarget(planning::PlanningService::Stub& stub,
                                            const SuccessRegion& region,
                                            const GroundTruthGrid& grid,
                                            const Eigen::Vector2d& start) {
  // Which point of the success region is nearest by path: a region cell, not the free cell
  // nearest an instance's centre, which can lie on the far side of a long counter or a wall.
  const std::optional<NearestGoal> nearest = NearestSuccessPoint(region, grid, start);
  if (!nearest.has_value())
    return absl::NotFoundError("no point of the success region is reachable");
  // The length itself is planning's A* to that cell.
  planning::PlanPathRequest request;
  *request.mutable_source()->mutable_grid() = ToGridMap(grid);
  request.mutable_start()->set_x(start.x());
  request.mutable_start()->set_y(start.y());
  request.mutable_goal()->set_x(nearest->goal.x());
  request.mutable_goal()->set_y(nearest->goal.y());
  request.set_planner(planning::PLANNER_KIND_ASTAR);
  request.set_robot_radius_m(0.0);  // the raster is already inflated by the robot radius
  planning::PlanPathResponse response;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(30));
  const grpc::Status status = stub.PlanPath(&context, request, &response);
  if (!status.ok())
    return absl::UnavailableError(absl::StrCat("PlanPath: ", status.error_message()));
  return response.length_m();
}

}  // namespace semnav::sim::loop
