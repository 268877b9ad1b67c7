#pragma once

#include <grpcpp/channel.h>

#include <functional>
#include <memory>
#include <string>

#include "absl/status/status.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "services/common/server/worker_pool.h"
#include "services/planning/core/jump_astar_cache.h"
#include "services/planning/server/footprint_cache.h"
#include "services/planning/server/live_grid_cache.h"
#include "services/planning/server/planning_config.h"

namespace semnav::planning {

// gRPC adapter of semnav.planning.v1.PlanningService (callback API): turns
// requests into core planner calls on a worker pool, honours the call
// deadline and cancellation, and returns typed PlanFailureDetail errors.
class PlanningServiceImpl final : public semnav::planning::v1::PlanningService::CallbackService {
 public:
  // `mapping` is the channel to the mapping service for live-map requests.
  PlanningServiceImpl(PlanningConfig config, std::shared_ptr<grpc::Channel> mapping);

  grpc::ServerUnaryReactor* PlanPath(grpc::CallbackServerContext* context,
                                     const semnav::planning::v1::PlanPathRequest* request,
                                     semnav::planning::v1::PlanPathResponse* response) override;

  grpc::ServerUnaryReactor* ExtractFrontiers(
      grpc::CallbackServerContext* context,
      const semnav::planning::v1::ExtractFrontiersRequest* request,
      semnav::planning::v1::ExtractFrontiersResponse* response) override;

  grpc::ServerUnaryReactor* ScoreFrontiers(
      grpc::CallbackServerContext* context,
      const semnav::planning::v1::ScoreFrontiersRequest* request,
      semnav::planning::v1::ScoreFrontiersResponse* response) override;

  grpc::ServerUnaryReactor* SelectExplorationGoal(
      grpc::CallbackServerContext* context,
      const semnav::planning::v1::SelectExplorationGoalRequest* request,
      semnav::planning::v1::SelectExplorationGoalResponse* response) override;

  grpc::ServerUnaryReactor* SmoothTrajectory(
      grpc::CallbackServerContext* context,
      const semnav::planning::v1::SmoothTrajectoryRequest* request,
      semnav::planning::v1::SmoothTrajectoryResponse* response) override;

  // Finishes queued searches and refreshes and stops their threads.
  void Shutdown() {
    refresher_.Shutdown();
    workers_.Shutdown();
  }

 private:
  absl::Status Plan(grpc::CallbackServerContext* context,
                    const semnav::planning::v1::PlanPathRequest& request,
                    semnav::planning::v1::PlanPathResponse* response);
  // Runs fn() on a worker and finishes the call with its status.
  grpc::ServerUnaryReactor* Serve(grpc::CallbackServerContext* context,
                                  std::function<absl::Status()> fn);
  // Serve() for requests with a GridSource: fn gets the resolved grid and
  // its field name.
  grpc::ServerUnaryReactor* ServeOnGrid(
      grpc::CallbackServerContext* context, const semnav::planning::v1::GridSource& source,
      std::function<absl::Status(const semnav::common::v1::GridMap&, const std::string&)> fn);
  // The request's grid: the inline one, or the live map (a grid fetched within the request's
  // max_age_ms, or fetched now); *field names it for errors ("source.grid" / "source.live_map").
  absl::StatusOr<std::shared_ptr<const semnav::common::v1::GridMap>> ResolveGrid(
      grpc::CallbackServerContext* context, const semnav::planning::v1::GridSource& source,
      std::string* field);
  // Fetches `live`'s window again on refresher_ and keeps it (LiveGridCache::ClaimRefresh).
  void RefreshAhead(const semnav::planning::v1::LiveMapGrid& live);

  const PlanningConfig config_;
  std::unique_ptr<semnav::mapping::v1::MappingService::Stub> mapping_;
  LiveGridCache live_grids_;
  FootprintCache footprints_;  // of the kept grids, for PlanPath's 2D planners
  // Per-map Jump A* state; its landmark builds run on workers_, which is
  // declared after it so it drains them before the cache goes.
  JumpAStarCache jump_astar_;
  semnav::WorkerPool workers_;
  // Refreshes ahead (one thread: one fetch at a time); last, so it stops first.
  semnav::WorkerPool refresher_;
};

}  // namespace semnav::planning
