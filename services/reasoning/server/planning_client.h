// PathPlanner over semnav-planning: PlanPath and SelectExplorationGoal on the mapping service's
// live map. Typed failures (PlanFailureDetail) become the core's codes: GOAL_OCCUPIED ->
// FAILED_PRECONDITION, NO_PATH -> NOT_FOUND. Any other failure (no map yet, robot outside the
// map, start occupied, timeout, planning down) returns an empty path so the robot plans locally,
// as it does without a planning service: motion never stops because planning is unavailable.
// Calls run under the gateway's lock, so they are only made on a READY channel: connecting (at
// start-up or after idleness) is kicked off in the background and meanwhile the robot plans
// locally / exploration falls back, instead of blocking gRPC threads on connection setup.
#pragma once

#include <memory>

#include <grpcpp/channel.h>

#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "services/reasoning/core/navigation_interfaces.h"
#include "services/reasoning/server/gateway_config.h"

namespace semnav::reasoning {

class PlanningClient : public PathPlanner {
 public:
  PlanningClient(std::shared_ptr<grpc::Channel> channel, PlanningSettings settings);

  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) override;
  absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery& query) override;

 private:
  bool Ready(const char* call);

  std::shared_ptr<grpc::Channel> channel_;
  std::unique_ptr<planning::v1::PlanningService::Stub> stub_;
  PlanningSettings settings_;
  planning::v1::ExplorationStrategy strategy_;
};

}  // namespace semnav::reasoning
