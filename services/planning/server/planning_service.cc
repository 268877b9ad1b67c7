#include "services/planning/server/planning_service.h"

#include <grpcpp/client_context.h>

#include <chrono>
#include <cmath>
#include <memory>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "services/common/status/grpc_status.h"
#include "services/planning/core/layered_inflation.h"
#include "services/planning/core/plan_failure.h"
#include "services/planning/server/exploration_rpc.h"
#include "services/planning/server/grid_conversion.h"
#include "services/planning/server/plan_response.h"
#include "services/planning/server/request_checks.h"
#include "services/planning/server/trajectory_rpc.h"

namespace semnav::planning {
namespace {

namespace pb = semnav::planning::v1;
using semnav::common::v1::GridMap;

absl::Status Invalid(absl::string_view field, absl::string_view message) {
  return FieldError(absl::StatusCode::kInvalidArgument, field, message);
}

bool NonNegative(double v) { return std::isfinite(v) && v >= 0.0; }

// A robot wider than this is no robot this planner serves.
constexpr double kMaxRobotRadiusM = 100.0;

// The earliest of the call deadline (less the margin for the reply), the
// request budget and the config cap.
absl::Time SearchDeadline(const grpc::CallbackServerContext& context, uint32_t request_ms,
                          const PlanningConfig& config) {
  absl::Time deadline = absl::Now() + absl::Milliseconds(config.max_planning_time_ms);
  if (request_ms > 0) deadline = std::min(deadline, absl::Now() + absl::Milliseconds(request_ms));
  const auto call = context.deadline();
  if (call != std::chrono::system_clock::time_point::max()) {
    deadline =
        std::min(deadline, absl::FromChrono(call) - absl::Milliseconds(config.deadline_margin_ms));
  }
  return deadline;
}

absl::Status CheckRequest(const pb::PlanPathRequest& request) {
  if (!pb::PlannerKind_IsValid(request.planner())) {
    return Invalid("planner", "unknown planner kind");
  }
  if (!NonNegative(request.robot_radius_m()) || request.robot_radius_m() > kMaxRobotRadiusM) {
    return Invalid("robot_radius_m", absl::StrCat("robot_radius_m must be a finite value in [0, ",
                                                  kMaxRobotRadiusM, "]"));
  }
  if (!NonNegative(request.goal_tolerance_m()) || request.goal_tolerance_m() > kMaxPathM) {
    return Invalid("goal_tolerance_m",
                   absl::StrCat("goal_tolerance_m must be a finite value in [0, ", kMaxPathM, "]"));
  }
  if (request.allow_alternative_point() && !request.has_first_sighting()) {
    return Invalid("first_sighting", "first_sighting is required when allow_alternative_point");
  }
  // Checked whenever sent, used or not: a NaN is a client bug either way.
  if (request.has_first_sighting()) {
    if (absl::Status s = CheckPose2D(request.first_sighting(), "first_sighting"); !s.ok()) return s;
  }
  if (request.contacts_size() > kMaxContacts) {
    return Invalid("contacts", absl::StrCat("at most ", kMaxContacts, " contacts"));
  }
  for (int i = 0; i < request.contacts_size(); ++i) {
    if (absl::Status s = CheckPose2D(request.contacts(i), absl::StrCat("contacts[", i, "]"));
        !s.ok())
      return s;
  }
  const pb::MultiModalOptions& mm = request.multimodal();
  if (mm.has_alpha() && (!NonNegative(mm.alpha()) || mm.alpha() > kMaxScore)) {
    return Invalid("multimodal.alpha",
                   absl::StrCat("alpha must be a finite value in [0, ", kMaxScore, "]"));
  }
  if (mm.has_beta() && (!NonNegative(mm.beta()) || mm.beta() > kMaxScore)) {
    return Invalid("multimodal.beta",
                   absl::StrCat("beta must be a finite value in [0, ", kMaxScore, "]"));
  }
  return absl::OkStatus();
}

absl::Status FetchLiveGrid(semnav::mapping::v1::MappingService::Stub& mapping,
                           std::chrono::system_clock::time_point deadline,
                           const pb::LiveMapGrid& live, GridMap* grid) {
  semnav::mapping::v1::GetGridMapRequest fetch;
  // Only the layers grid_conversion reads: mapping then skips the semantic layer, most of a
  // GetGridMap's cost (callgrind, docs/performance/gateway.md).
  for (const semnav::common::v1::GridLayerKind kind :
       {semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL,
        semnav::common::v1::GRID_LAYER_KIND_OCCUPANCY,
        semnav::common::v1::GRID_LAYER_KIND_OBSTACLE_PROBABILITY,
        semnav::common::v1::GRID_LAYER_KIND_EXPLORED}) {
    fetch.add_layers(kind);
  }
  if (live.has_window_min() || live.has_window_max()) {
    fetch.mutable_window()->mutable_min()->set_x(live.window_min().x());
    fetch.mutable_window()->mutable_min()->set_y(live.window_min().y());
    fetch.mutable_window()->mutable_max()->set_x(live.window_max().x());
    fetch.mutable_window()->mutable_max()->set_y(live.window_max().y());
  }
  grpc::ClientContext call;
  call.set_deadline(deadline);
  semnav::mapping::v1::GetGridMapResponse reply;
  const grpc::Status status = mapping.GetGridMap(&call, fetch, &reply);
  if (!status.ok()) {
    const absl::Status mapped = FromGrpcStatus(status);
    const absl::StatusCode code = mapped.code() == absl::StatusCode::kInvalidArgument
                                      ? absl::StatusCode::kInvalidArgument
                                      : absl::StatusCode::kUnavailable;
    return FieldError(code, "source.live_map",
                      absl::StrCat("mapping service GetGridMap failed: ", status.error_message()),
                      "MAPPING_UNAVAILABLE");
  }
  *grid = std::move(*reply.mutable_grid());
  return absl::OkStatus();
}

}  // namespace

PlanningServiceImpl::PlanningServiceImpl(PlanningConfig config,
                                         std::shared_ptr<grpc::Channel> mapping)
    : config_(std::move(config)),
      mapping_(semnav::mapping::v1::MappingService::NewStub(std::move(mapping))),
      jump_astar_(static_cast<size_t>(config_.jump_astar_cache_mb) << 20,
                  [this](std::function<void()> job) { (void)workers_.Submit(std::move(job)); }),
      workers_(config_.worker_threads),
      refresher_(1) {}

grpc::ServerUnaryReactor* PlanningServiceImpl::Serve(grpc::CallbackServerContext* context,
                                                     std::function<absl::Status()> fn) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  if (!workers_.Submit([reactor, fn = std::move(fn)] { reactor->Finish(ToGrpcStatus(fn())); })) {
    reactor->Finish(grpc::Status(grpc::StatusCode::UNAVAILABLE, "planning is shutting down"));
  }
  return reactor;
}

grpc::ServerUnaryReactor* PlanningServiceImpl::PlanPath(grpc::CallbackServerContext* context,
                                                        const pb::PlanPathRequest* request,
                                                        pb::PlanPathResponse* response) {
  return Serve(context, [=, this] { return Plan(context, *request, response); });
}

grpc::ServerUnaryReactor* PlanningServiceImpl::ServeOnGrid(
    grpc::CallbackServerContext* context, const pb::GridSource& source,
    std::function<absl::Status(const GridMap&, const std::string&)> fn) {
  return Serve(context, [=, this]() -> absl::Status {
    std::string field;
    absl::StatusOr<std::shared_ptr<const GridMap>> grid = ResolveGrid(context, source, &field);
    if (!grid.ok()) return grid.status();
    return fn(**grid, field);
  });
}

grpc::ServerUnaryReactor* PlanningServiceImpl::ExtractFrontiers(
    grpc::CallbackServerContext* context, const pb::ExtractFrontiersRequest* request,
    pb::ExtractFrontiersResponse* response) {
  return ServeOnGrid(context, request->source(),
                     [=, this](const GridMap& grid, const std::string& field) {
                       return ExtractFrontiersOn(grid, field, *request, config_, response);
                     });
}

grpc::ServerUnaryReactor* PlanningServiceImpl::ScoreFrontiers(
    grpc::CallbackServerContext* context, const pb::ScoreFrontiersRequest* request,
    pb::ScoreFrontiersResponse* response) {
  return Serve(context, [=, this] { return ScoreFrontiersOn(*request, config_, response); });
}

grpc::ServerUnaryReactor* PlanningServiceImpl::SelectExplorationGoal(
    grpc::CallbackServerContext* context, const pb::SelectExplorationGoalRequest* request,
    pb::SelectExplorationGoalResponse* response) {
  return ServeOnGrid(context, request->source(),
                     [=, this](const GridMap& grid, const std::string& field) {
                       return SelectGoalOn(grid, field, *request, config_, response);
                     });
}

grpc::ServerUnaryReactor* PlanningServiceImpl::SmoothTrajectory(
    grpc::CallbackServerContext* context, const pb::SmoothTrajectoryRequest* request,
    pb::SmoothTrajectoryResponse* response) {
  return ServeOnGrid(context, request->source(),
                     [=, this](const GridMap& grid, const std::string& field) {
                       return SmoothTrajectoryOn(grid, field, *request, config_.trajectory,
                                                 config_.occupied_percent, response);
                     });
}

absl::StatusOr<std::shared_ptr<const GridMap>> PlanningServiceImpl::ResolveGrid(
    grpc::CallbackServerContext* context, const pb::GridSource& source, std::string* field) {
  switch (source.source_case()) {
    case pb::GridSource::kGrid:
      *field = "source.grid";
      // Not owned: the request outlives the call.
      return std::shared_ptr<const GridMap>(std::shared_ptr<const GridMap>(), &source.grid());
    case pb::GridSource::kLiveMap: {
      *field = "source.live_map";
      const pb::LiveMapGrid& live = source.live_map();
      if (live.max_age_ms() > kMaxLiveGridAgeMs) {
        return Invalid("source.live_map.max_age_ms",
                       absl::StrCat("max_age_ms must be at most ", kMaxLiveGridAgeMs));
      }
      const absl::Time now = absl::Now();
      const absl::Duration max_age = absl::Milliseconds(live.max_age_ms());
      if (std::shared_ptr<const GridMap> kept = live_grids_.Find(live, now, max_age)) {
        if (config_.live_map_refresh_ahead > 0.0 &&
            live_grids_.ClaimRefresh(live, now, max_age * config_.live_map_refresh_ahead)) {
          RefreshAhead(live);
        }
        return kept;
      }
      auto fetched = std::make_shared<GridMap>();
      if (absl::Status s = FetchLiveGrid(*mapping_, context->deadline(), live, fetched.get());
          !s.ok()) {
        return s;
      }
      // Kept for later calls that accept its age, whatever this one asked.
      live_grids_.Put(live, fetched, now);
      return std::shared_ptr<const GridMap>(std::move(fetched));
    }
    default:
      return Invalid("source", "set source.grid (inline) or source.live_map");
  }
}

void PlanningServiceImpl::RefreshAhead(const pb::LiveMapGrid& live) {
  const bool queued = refresher_.Submit([this, live] {
    // A fetch the caller does not wait for: a deadline of its own, the same as a search's cap.
    const auto deadline =
        std::chrono::system_clock::now() + std::chrono::milliseconds(config_.max_planning_time_ms);
    auto fetched = std::make_shared<GridMap>();
    const absl::Time started = absl::Now();
    if (FetchLiveGrid(*mapping_, deadline, live, fetched.get()).ok()) {
      live_grids_.Put(live, std::move(fetched), started);
    } else {
      live_grids_.EndRefresh(live);  // the next call that needs a fetch makes it itself
    }
  });
  if (!queued) live_grids_.EndRefresh(live);
}

absl::Status PlanningServiceImpl::Plan(grpc::CallbackServerContext* context,
                                       const pb::PlanPathRequest& request,
                                       pb::PlanPathResponse* response) {
  if (absl::Status s = CheckRequest(request); !s.ok()) return s;
  const absl::Time started = absl::Now();
  std::string grid_field;
  absl::StatusOr<std::shared_ptr<const GridMap>> resolved =
      ResolveGrid(context, request.source(), &grid_field);
  if (!resolved.ok()) return resolved.status();
  std::shared_ptr<const GridMap> grid = *std::move(resolved);
  absl::StatusOr<GridFrame> frame = ReadGridFrame(*grid, grid_field);
  if (!frame.ok()) return frame.status();
  if (request.contacts_size() > 0) {
    // A copy of its own: the kept live grid stays as mapping drew it for other calls.
    auto stamped = std::make_shared<GridMap>(*grid);
    std::vector<Eigen::Vector2d> contacts;
    for (const semnav::common::v1::Pose2D& c : request.contacts())
      contacts.emplace_back(c.x(), c.y());
    StampContacts(contacts, config_.contact_radius_m, *stamped);
    grid = std::move(stamped);
  }
  const GridMap& map = *grid;
  // 2D planners pad the grid to a start just outside it (GridPlannerConfig::max_start_outside_m).
  absl::StatusOr<Cell> start = request.planner() == pb::PLANNER_KIND_JUMP_ASTAR
                                   ? frame->ToCell(request.start(), "start")
                                   : frame->ToCellAnywhere(request.start(), "start");
  if (!start.ok()) return start.status();
  absl::StatusOr<Cell> goal = request.planner() == pb::PLANNER_KIND_JUMP_ASTAR
                                  ? frame->ToCell(request.goal(), "goal")
                                  : frame->ToCellAnywhere(request.goal(), "goal");
  if (!goal.ok()) return goal.status();

  SearchLimits limits;
  limits.deadline = SearchDeadline(*context, request.max_planning_time_ms(), config_);
  limits.is_cancelled = [context] { return context->IsCancelled(); };

  absl::Status failure;
  if (request.planner() == pb::PLANNER_KIND_JUMP_ASTAR) {
    absl::StatusOr<LayeredGrid> grid = ToLayeredGrid(map, config_.unknown_is_free, grid_field);
    if (!grid.ok()) return grid.status();
    JumpAStarOptions options = config_.jump_astar;
    options.resolution_m = frame->resolution;
    if (request.multimodal().has_alpha()) options.alpha = request.multimodal().alpha();
    if (request.multimodal().has_beta()) options.beta = request.multimodal().beta();
    if (options.alpha + options.beta <= 0.0) {
      return Invalid("multimodal.alpha", "alpha and beta must not both be 0");
    }
    // The footprint (robot_radius_m): rolling keeps the radius from obstacles, flying clears the
    // tallest one within it, structure stays that far away. A start the inflation walls in (the
    // robot stands near a wall) moves to the nearest passable cell within start_snap_radius_m.
    const double radius_cells = request.robot_radius_m() / frame->resolution;
    const LayeredGrid inflated = InflateLayeredGrid(*grid, radius_cells);
    Cell from = *start;
    if (inflated.Contains(from) && !Passable(inflated, from.x, from.y) &&
        Passable(*grid, from.x, from.y)) {
      const std::optional<Cell> snapped = NearestPassableCell(
          inflated, from, config_.grid_planner.start_snap_radius_m / frame->resolution);
      if (snapped.has_value()) from = *snapped;
    }
    // A goal the inflation walls in (a frontier or a view point near a wall) moves the same way,
    // within goal_tolerance_m.
    Cell to = *goal;
    if (inflated.Contains(to) && !Passable(inflated, to.x, to.y) && Passable(*grid, to.x, to.y)) {
      const std::optional<Cell> snapped =
          NearestPassableCell(inflated, to, request.goal_tolerance_m() / frame->resolution);
      if (snapped.has_value()) to = *snapped;
    }
    absl::StatusOr<MultiModalPath> path = jump_astar_.Plan(inflated, from, to, options, limits);
    if (path.ok()) {
      if (!(from == *start)) PrependStart(*start, options, &*path);
      FillResponse(*frame, *path,
                   FlightHeights{map.foot_height(), map.ceiling_height(), config_.flight_margin_m},
                   response);
      response->set_start_adjusted(!(from == *start));
      response->set_goal_adjusted(!(to == *goal));
      *response->mutable_planned_start() = frame->ToPose(from);
    }
    failure = path.status();
  } else {
    absl::StatusOr<PassabilityGrid> free =
        ToPassability(map, {config_.occupied_percent, config_.unknown_is_free}, grid_field);
    if (!free.ok()) return free.status();
    GridPlanRequest plan;
    plan.free = *std::move(free);
    plan.obstacle_probability = ToObstacleProbability(map);
    plan.resolution_m = frame->resolution;
    plan.start = *start;
    plan.goal = *goal;
    plan.robot_radius_m = request.robot_radius_m();
    plan.goal_tolerance_m = request.goal_tolerance_m();
    if (request.allow_alternative_point()) {
      absl::StatusOr<Cell> sighting = frame->ToCell(request.first_sighting(), "first_sighting");
      if (!sighting.ok()) return sighting.status();
      plan.first_sighting = *sighting;
    }
    plan.use_jps = request.planner() != pb::PLANNER_KIND_ASTAR;
    plan.keep_clearance = request.keep_clearance();
    plan.outside_is_free = config_.unknown_is_free;
    plan.limits = limits;
    GridPlanner planner(config_.grid_planner);
    // A grid stamped with contacts is this call's alone: prepared, not kept (an empty owner).
    const std::shared_ptr<const GridMap> kept_grid = request.contacts_size() > 0 ? nullptr : grid;
    plan.prepared = footprints_.Get(kept_grid, plan.robot_radius_m, plan.keep_clearance, [&] {
      return planner.Prepare(plan.free, plan.resolution_m, plan.robot_radius_m,
                             plan.keep_clearance);
    });
    absl::StatusOr<GridPlanResult> result = planner.Plan(plan);
    if (result.ok()) FillResponse(*frame, *result, response);
    failure = result.status();
  }
  if (!failure.ok()) {
    AttachPlanFailure(failure, Cell{std::max(start->x, 0), std::max(start->y, 0)},
                      Cell{std::max(goal->x, 0), std::max(goal->y, 0)});
    return failure;
  }
  response->set_planning_time_ms(absl::ToDoubleMilliseconds(absl::Now() - started));
  response->set_map_revision(map.revision());
  return absl::OkStatus();
}

}  // namespace semnav::planning
