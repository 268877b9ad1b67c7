#include "clients/sim/loop/shortest_path.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include <grpcpp/grpcpp.h>

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

absl::StatusOr<double> ShortestPathToTarget(planning::PlanningService::Stub& stub, const World& world,
                                            const GroundTruthGrid& grid, const Eigen::Vector2d& start,
                                            const std::string& label, double success_radius) {
  planning::PlanPathRequest request;
  *request.mutable_source()->mutable_grid() = ToGridMap(grid);
  request.mutable_start()->set_x(start.x());
  request.mutable_start()->set_y(start.y());
  request.set_planner(planning::PLANNER_KIND_ASTAR);
  request.set_robot_radius_m(0.0);  // the raster is already inflated by the robot radius
  double best = std::numeric_limits<double>::infinity();
  for (const ObjectInstance& object : world.objects) {
    if (object.label != label) continue;
    // The footprint is occupied: the planner moves the goal to the free reachable cell nearest
    // the centre; it counts only if that cell is within the success radius of the footprint.
    request.mutable_goal()->set_x(object.box.center.x());
    request.mutable_goal()->set_y(object.box.center.y());
    request.set_goal_tolerance_m(object.box.size.head<2>().norm() / 2.0 + success_radius);
    planning::PlanPathResponse response;
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(30));
    const grpc::Status status = stub.PlanPath(&context, request, &response);
    if (status.error_code() == grpc::StatusCode::NOT_FOUND ||
        status.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
      continue;  // unreachable instance
    }
    if (!status.ok()) return absl::UnavailableError(absl::StrCat("PlanPath: ", status.error_message()));
    const Eigen::Vector2d goal(response.planned_goal().x(), response.planned_goal().y());
    if (DistanceToNearestInstance(world, label, goal) > success_radius + grid.resolution) continue;
    best = std::min(best, response.length_m());
  }
  if (best == std::numeric_limits<double>::infinity()) {
    return absl::NotFoundError(absl::StrCat("no reachable instance of \"", label, "\""));
  }
  return best;
}

}  // namespace semnav::sim::loop
