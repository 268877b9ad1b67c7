// PathPlanner over semnav-planning: PlanPath and SelectExplorationGoal on the mapping service's
// live map. Typed failures (PlanFailureDetail) become the core's codes: GOAL_OCCUPIED ->
// FAILED_PRECONDITION, NO_PATH -> NOT_FOUND. Planning unreachable, too slow or not connected
// (UNAVAILABLE, DEADLINE_EXCEEDED, channel not READY), or answering UNAVAILABLE because its
// live map's mapping call failed, becomes DependencyUnavailableError naming "planning" or
// "mapping": the executor pauses the task rather than send the robot blind goals. Other failures
// (no map yet, robot outside the map, start occupied) return an empty path so the robot plans
// locally. Calls run under the gateway's lock, so they are only made on a READY channel:
// connecting (at start-up or after idleness) is kicked off in the background and meanwhile the
// planner answers UNAVAILABLE (the task retries), instead of blocking gRPC threads.
#pragma once

#include <grpcpp/channel.h>

#include <memory>

#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "services/reasoning/core/navigation_interfaces.h"
#include "services/reasoning/core/per_task_path_planner.h"
#include "services/reasoning/server/gateway_config.h"

namespace semnav::reasoning {

// EROI_UTILITY: the live-map window whose EROIs are the context's columns, and their values.
void AddEroiValues(const ExplorationContext& context,
                   planning::v1::SelectExplorationGoalRequest* request);

// The robot's waypoints for a PlanPath answer to `query`. 2D paths keep the goal's z. Multi-modal
// paths put rolling points on the floor (z = 0) and flying segments at their altitude_m: the
// robot climbs straight up where a flying segment begins and lands straight down where the next
// rolling one begins, so it never slants into what it flies over; the first point keeps the
// robot's own altitude (start z).
std::vector<Eigen::Vector3d> RobotPath(const planning::v1::PlanPathResponse& response,
                                       const PathQuery& query);

// SelectGoal sends the task's SemanticContext (SEMANTIC_FRONTIER's language and grounding inputs);
// ExplorationGoal without a task asks with the configured strategy and no context.
class PlanningClient : public PathPlanner, public ExplorationService {
 public:
  PlanningClient(std::shared_ptr<grpc::Channel> channel, PlanningSettings settings);

  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) override;
  absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery& query) override;
  absl::StatusOr<Eigen::Vector3d> SelectGoal(const ExplorationQuery& query,
                                             std::optional<ExplorationStrategy> strategy,
                                             const ExplorationContext& context) override;

 private:
  absl::Status Ready(const char* call);
  // `length_m` exceeds `than_m` by clearance_detour_factor and by clearance_detour_m.
  bool MuchLonger(double length_m, double than_m) const;
  grpc::Status Select(const planning::v1::SelectExplorationGoalRequest& request,
                      planning::v1::SelectExplorationGoalResponse* response);

  std::shared_ptr<grpc::Channel> channel_;
  std::unique_ptr<planning::v1::PlanningService::Stub> stub_;
  PlanningSettings settings_;
};

}  // namespace semnav::reasoning
