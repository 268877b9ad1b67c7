#include "clients/sim/loop/local_planner.h"

#include <grpcpp/grpcpp.h>

#include <chrono>

#include "absl/strings/str_cat.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"

namespace semnav::sim::loop {

namespace planning = semnav::planning::v1;

// How far around start and goal the live-map window reaches, metres: room to go around walls.
constexpr double kWindowMargin = 4.0;
// Goals of exploration may sit in a wall the robot has just seen; move them this far at most.
constexpr double kGoalTolerance = 1.0;
// Beyond the footprint radius, metres (the gateway's executor.path_clearance_m default).
constexpr double kClearance = 0.1;

LocalPlanFn LiveMapPlanner(const std::shared_ptr<grpc::Channel>& channel, double robot_radius) {
  std::shared_ptr<planning::PlanningService::Stub> stub =
      planning::PlanningService::NewStub(channel);
  return [stub, robot_radius](
             const Eigen::Vector2d& from,
             const Eigen::Vector2d& to) -> absl::StatusOr<std::vector<Eigen::Vector2d>> {
    planning::PlanPathRequest request;
    planning::LiveMapGrid* live = request.mutable_source()->mutable_live_map();
    live->mutable_window_min()->set_x(std::min(from.x(), to.x()) - kWindowMargin);
    live->mutable_window_min()->set_y(std::min(from.y(), to.y()) - kWindowMargin);
    live->mutable_window_max()->set_x(std::max(from.x(), to.x()) + kWindowMargin);
    live->mutable_window_max()->set_y(std::max(from.y(), to.y()) + kWindowMargin);
    request.mutable_start()->set_x(from.x());
    request.mutable_start()->set_y(from.y());
    request.mutable_goal()->set_x(to.x());
    request.mutable_goal()->set_y(to.y());
    request.set_planner(planning::PLANNER_KIND_ASTAR);
    request.set_goal_tolerance_m(kGoalTolerance);
    planning::PlanPathResponse response;
    grpc::Status status;
    // Paths keep a clearance beyond the footprint, as the gateway's do (mapped walls are off by
    // a cell or two). Next to an obstacle the inflated start is occupied: plan with the bare
    // footprint, then as a point robot to get out (the simulator still reports any contact).
    for (double radius : {robot_radius + kClearance, robot_radius, 0.0}) {
      request.set_robot_radius_m(radius);
      grpc::ClientContext context;
      context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(60));
      status = stub->PlanPath(&context, request, &response);
      if (status.error_code() != grpc::StatusCode::FAILED_PRECONDITION) break;
    }
    if (!status.ok())
      return absl::UnavailableError(absl::StrCat("local plan: ", status.error_message()));
    std::vector<Eigen::Vector2d> path;
    for (int i = 1; i < response.path_size(); ++i)
      path.emplace_back(response.path(i).x(), response.path(i).y());
    return path;
  };
}

}  // namespace semnav::sim::loop
