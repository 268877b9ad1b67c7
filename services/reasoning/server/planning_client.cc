#include "services/reasoning/server/planning_client.h"

#include <grpcpp/client_context.h>

#include <algorithm>
#include <chrono>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/common/status/grpc_status.h"

namespace semnav::reasoning {
namespace {

namespace pb = ::semnav::planning::v1;

void SetPose(const Eigen::Vector3d& point, common::v1::Pose2D* out) {
  out->set_x(point.x());
  out->set_y(point.y());
}

void SetDeadline(grpc::ClientContext& context, int deadline_ms) {
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::milliseconds(deadline_ms));
}

// Planning unreachable or too slow (or mapping behind it): the task pauses rather than drive
// blind. Other failures (no map yet, robot outside the map, start occupied) keep the fallback.
bool DependencyGone(const grpc::Status& status) {
  return status.error_code() == grpc::StatusCode::UNAVAILABLE ||
         status.error_code() == grpc::StatusCode::DEADLINE_EXCEEDED;
}

absl::Status Unavailable(const char* call, const grpc::Status& status) {
  // Planning answers UNAVAILABLE naming its live map's GetGridMap when mapping is the one gone.
  const bool mapping =
      status.error_code() == grpc::StatusCode::UNAVAILABLE &&
      absl::StrContains(status.error_message(), "mapping service GetGridMap failed");
  LogWarning("planning_unavailable", {{"call", call},
                                      {"code", static_cast<int>(status.error_code())},
                                      {"message", status.error_message()},
                                      {"dependency", mapping ? "mapping" : "planning"}});
  return DependencyUnavailableError(mapping ? "mapping" : "planning",
                                    absl::StrCat(call, ": ", status.error_message()));
}

// The one place a core strategy becomes planning's proto enum.
pb::ExplorationPlatform ToProto(RobotPlatform platform) {
  switch (platform) {
    case RobotPlatform::kGround:
      return pb::EXPLORATION_PLATFORM_GROUND;
    case RobotPlatform::kAerial:
      return pb::EXPLORATION_PLATFORM_AERIAL;
    case RobotPlatform::kUnspecified:
      return pb::EXPLORATION_PLATFORM_UNSPECIFIED;
  }
  return pb::EXPLORATION_PLATFORM_UNSPECIFIED;
}

pb::ExplorationStrategy ToProto(ExplorationStrategy strategy) {
  switch (strategy) {
    case ExplorationStrategy::kNearestFrontier:
      return pb::EXPLORATION_STRATEGY_NEAREST_FRONTIER;
    case ExplorationStrategy::kCoverageMax:
      return pb::EXPLORATION_STRATEGY_COVERAGE_MAX;
    case ExplorationStrategy::kSemanticFrontier:
      return pb::EXPLORATION_STRATEGY_SEMANTIC_FRONTIER;
    case ExplorationStrategy::kEroiUtility:
      return pb::EXPLORATION_STRATEGY_EROI_UTILITY;
  }
  return pb::EXPLORATION_STRATEGY_UNSPECIFIED;
}

}  // namespace

void AddEroiValues(const ExplorationContext& context, pb::SelectExplorationGoalRequest* request) {
  // Mapping includes both corner cells of a window, so the far corner is pulled in by a quarter
  // edge: ceil(cells / edge) then counts exactly the gateway's columns at any map resolution
  // finer than a quarter edge.
  pb::LiveMapGrid* live = request->mutable_source()->mutable_live_map();
  live->mutable_window_min()->set_x(context.eroi_window_min.x());
  live->mutable_window_min()->set_y(context.eroi_window_min.y());
  live->mutable_window_max()->set_x(context.eroi_window_max.x() - context.eroi_edge_m / 4.0);
  live->mutable_window_max()->set_y(context.eroi_window_max.y() - context.eroi_edge_m / 4.0);
  for (double value : context.eroi_values) request->add_eroi_semantic_values(value);
  request->set_eroi_size_m(context.eroi_edge_m);  // the values are per the gateway's EROIs
}

std::vector<Eigen::Vector3d> RobotPath(const pb::PlanPathResponse& response,
                                       const PathQuery& query) {
  std::vector<Eigen::Vector3d> path;
  auto xy = [&](int i) { return Eigen::Vector2d(response.path(i).x(), response.path(i).y()); };
  if (!query.multi_modal || response.path_size() == 0) {
    for (int i = 0; i < response.path_size(); ++i)
      path.emplace_back(xy(i).x(), xy(i).y(), query.goal.z());
    return path;
  }
  auto add = [&](const Eigen::Vector2d& p, double z) {
    if (!path.empty() && path.back().head<2>() == p && path.back().z() == z) return;
    path.emplace_back(p.x(), p.y(), z);
  };
  add(xy(0), query.start.z());
  for (const pb::PathSegment& s : response.segments()) {
    const double z = s.mode() == pb::MOTION_MODE_FLYING ? s.altitude_m() : 0.0;
    const int first = static_cast<int>(s.first_point());
    const int last = std::min(static_cast<int>(s.last_point()), response.path_size() - 1);
    if (first > last) continue;
    add(xy(first), z);  // straight up or down where the mode (or the altitude) changes
    for (int i = first + 1; i <= last; ++i) add(xy(i), z);
  }
  return path;
}

bool PlanningClient::MuchLonger(double length_m, double than_m) const {
  return settings_.clearance_detour_factor > 0.0 &&
         length_m > settings_.clearance_detour_factor * than_m &&
         length_m - than_m > settings_.clearance_detour_m;
}

PlanningClient::PlanningClient(std::shared_ptr<grpc::Channel> channel, PlanningSettings settings)
    : channel_(channel),
      stub_(pb::PlanningService::NewStub(channel)),
      settings_(std::move(settings)) {
  channel_->GetState(/*try_to_connect=*/true);
}

absl::Status PlanningClient::Ready(const char* call) {
  // A channel still connecting (the gateway has just started, or planning has just come back)
  // gets a moment before the task pauses; a refused connection ends the wait at once.
  constexpr auto kConnectWait = std::chrono::milliseconds(500);
  const auto deadline = std::chrono::system_clock::now() + kConnectWait;
  grpc_connectivity_state state = channel_->GetState(/*try_to_connect=*/true);
  while (state == GRPC_CHANNEL_IDLE || state == GRPC_CHANNEL_CONNECTING) {
    if (!channel_->WaitForStateChange(state, deadline)) break;
    state = channel_->GetState(/*try_to_connect=*/true);
  }
  if (state == GRPC_CHANNEL_READY) return absl::OkStatus();
  LogWarning("planning_not_connected", {{"call", call}, {"fallback", "task pauses"}});
  return DependencyUnavailableError("planning", absl::StrCat(call, ": not connected"));
}

absl::StatusOr<std::vector<Eigen::Vector3d>> PlanningClient::Plan(const PathQuery& query) {
  if (absl::Status ready = Ready("PlanPath"); !ready.ok()) return ready;
  pb::PlanPathRequest request;
  request.mutable_source()->mutable_live_map()->set_max_age_ms(query.live_map_max_age_ms);
  SetPose(query.start, request.mutable_start());
  SetPose(query.goal, request.mutable_goal());
  request.set_planner(query.multi_modal ? pb::PLANNER_KIND_JUMP_ASTAR : pb::PLANNER_KIND_JPS);
  request.set_goal_tolerance_m(query.goal_tolerance_m > 0.0 ? query.goal_tolerance_m
                                                            : settings_.goal_tolerance_m);
  request.set_keep_clearance(
      true);  // the robot's path keeps away from obstacles (planning.clearance)
  for (const Eigen::Vector3d& contact : query.contacts) SetPose(contact, request.add_contacts());
  if (query.alternative_from.has_value()) {
    request.set_allow_alternative_point(true);
    SetPose(*query.alternative_from, request.mutable_first_sighting());
  }
  const auto started = std::chrono::steady_clock::now();
  pb::PlanPathResponse response;
  grpc::Status status;
  pb::PlanFailureReason reason = pb::PLAN_FAILURE_REASON_UNSPECIFIED;
  const auto plan_with = [&](double radius, pb::PlanPathResponse* answer) {
    request.set_robot_radius_m(radius);
    grpc::ClientContext context;
    SetDeadline(context, settings_.deadline_ms);
    const grpc::Status answered = stub_->PlanPath(&context, request, answer);
    const std::optional<pb::PlanFailureDetail> detail =
        answered.ok() ? std::nullopt : GetDetail<pb::PlanFailureDetail>(answered);
    reason = detail.has_value() ? detail->reason() : pb::PLAN_FAILURE_REASON_UNSPECIFIED;
    return answered;
  };
  // With the clearance first; when that inflates the robot's own position (it stands near a
  // wall) or leaves no way, with the bare footprint.
  const auto bare_footprint_may_help = [](pb::PlanFailureReason failure) {
    return failure == pb::PLAN_FAILURE_REASON_START_OCCUPIED ||
           failure == pb::PLAN_FAILURE_REASON_NO_PATH;
  };
  status = plan_with(query.robot_radius_m + query.clearance_m, &response);
  const bool footprint_may_help = bare_footprint_may_help(reason);
  std::vector<Eigen::Vector3d> way;  // the answer's path in the robot's terms, converted once
  if (!status.ok() && footprint_may_help && query.clearance_m > 0.0) {
    status = plan_with(query.robot_radius_m, &response);
  } else if (status.ok() && query.clearance_m > 0.0 && response.path_size() > 0) {
    // A way round where the short way passes a gap narrower than the footprint and the
    // clearance: the bare footprint's way is taken when it is much shorter. The clearance is a
    // preference, as Nav2's inflation cost is, not a wall.
    way = RobotPath(response, query);
    const double with_clearance = HorizontalLength(query.start, way);
    if (MuchLonger(with_clearance, (way.back() - query.start).head<2>().norm())) {
      pb::PlanPathResponse bare;  // its failure leaves the clearance's way
      if (plan_with(query.robot_radius_m, &bare).ok() && bare.path_size() > 0) {
        std::vector<Eigen::Vector3d> bare_way = RobotPath(bare, query);
        if (MuchLonger(with_clearance, HorizontalLength(query.start, bare_way))) {
          way = std::move(bare_way);
        }
      }
    }
  }
  // Contacts are a preference as well: one left where the robot brushed a door frame would close
  // the door for the rest of the task (mission bench: no_path in HouseExpo and office rooms). A
  // way they leave none of is planned without them.
  if (!status.ok() && request.contacts_size() > 0 &&
      (footprint_may_help || reason == pb::PLAN_FAILURE_REASON_GOAL_OCCUPIED)) {
    request.clear_contacts();
    status = plan_with(query.robot_radius_m + query.clearance_m, &response);
    if (!status.ok() && bare_footprint_may_help(reason) && query.clearance_m > 0.0)
      status = plan_with(query.robot_radius_m, &response);
  }
  if (!status.ok()) {
    if (reason == pb::PLAN_FAILURE_REASON_GOAL_OCCUPIED)
      return absl::FailedPreconditionError(status.error_message());
    if (reason == pb::PLAN_FAILURE_REASON_NO_PATH)
      return absl::NotFoundError(status.error_message());
    if (DependencyGone(status)) return Unavailable("PlanPath", status);
    LogWarning("planning_failed", {{"code", static_cast<int>(status.error_code())},
                                   {"message", status.error_message()},
                                   {"elapsed_ms", std::chrono::duration<double, std::milli>(
                                                      std::chrono::steady_clock::now() - started)
                                                      .count()},
                                   {"fallback", "robot plans locally"}});
    return std::vector<Eigen::Vector3d>{};
  }
  return way.empty() ? RobotPath(response, query) : way;
}

grpc::Status PlanningClient::Select(const pb::SelectExplorationGoalRequest& request,
                                    pb::SelectExplorationGoalResponse* response) {
  grpc::ClientContext call;
  SetDeadline(call, settings_.deadline_ms);
  return stub_->SelectExplorationGoal(&call, request, response);
}

absl::StatusOr<Eigen::Vector3d> PlanningClient::ExplorationGoal(const ExplorationQuery& query) {
  return SelectGoal(query, std::nullopt, ExplorationContext{});
}

absl::StatusOr<Eigen::Vector3d> PlanningClient::SelectGoal(
    const ExplorationQuery& query, std::optional<ExplorationStrategy> strategy,
    const ExplorationContext& context) {
  if (absl::Status ready = Ready("SelectExplorationGoal"); !ready.ok()) return ready;
  const RobotPose& pose = query.pose;
  pb::SelectExplorationGoalRequest request;
  request.mutable_source()->mutable_live_map()->set_max_age_ms(query.live_map_max_age_ms);
  SetPose(pose.position, request.mutable_robot());
  request.mutable_robot()->set_yaw(pose.yaw);
  const pb::ExplorationStrategy chosen = ToProto(strategy.value_or(settings_.exploration_strategy));
  // COVERAGE_MAX (a point ahead of the robot) and EROI_UTILITY (a viewpoint route) have no
  // frontier to see cleared: their goals are driven to the end, so the goal to keep is the answer.
  const bool look = context.look_at.has_value();
  if (!look && query.keep_goal.has_value() &&
      (chosen == pb::EXPLORATION_STRATEGY_COVERAGE_MAX ||
       chosen == pb::EXPLORATION_STRATEGY_EROI_UTILITY)) {
    return *query.keep_goal;
  }
  request.set_strategy(chosen);
  request.set_platform(ToProto(query.platform));
  for (const ExplorationHint& hint : context.objects) {
    pb::SemanticObject* object = request.mutable_semantics()->add_objects();
    object->set_label(hint.label);
    SetPose(hint.position, object->mutable_position());
    object->set_relevance(hint.relevance);
    object->set_relation(hint.relation);
    object->set_cooccurrence(hint.cooccurrence);
  }
  for (const Eigen::Vector3d& place : context.visited)
    SetPose(place, request.mutable_semantics()->add_visited());
  // A look needs the whole live map, not the EROI window.
  const bool eroi_values =
      !look && chosen == pb::EXPLORATION_STRATEGY_EROI_UTILITY && !context.eroi_values.empty();
  if (eroi_values) AddEroiValues(context, &request);
  for (const Eigen::Vector3d& goal : query.excluded_goals)
    SetPose(goal, request.add_excluded_goals());
  request.set_excluded_radius_m(query.excluded_radius_m);
  request.set_robot_radius_m(query.robot_radius_m);
  request.set_clearance_m(query.clearance_m);
  if (query.keep_goal.has_value() && !look) {
    SetPose(*query.keep_goal, request.mutable_keep_goal());
    request.set_keep_radius_m(query.keep_radius_m);
  }
  if (look) {
    SetPose(*context.look_at, request.mutable_look_at());
    request.set_look_distance_m(context.look_distance_m);
  }
  if (context.search_area.has_value()) {
    pb::SearchArea* area = request.mutable_search_area();
    area->set_min_x(context.search_area->min.x());
    area->set_min_y(context.search_area->min.y());
    area->set_max_x(context.search_area->max.x());
    area->set_max_y(context.search_area->max.y());
  }
  pb::SelectExplorationGoalResponse response;
  grpc::Status status = Select(request, &response);
  if (eroi_values && status.error_code() == grpc::StatusCode::INVALID_ARGUMENT) {
    // Our grid and planning's disagree (a planning that ignores eroi_size_m, or a window it
    // counts differently): explore on planning's uniform values rather than not at all.
    LogWarning("eroi_values_rejected",
               {{"message", status.error_message()}, {"fallback", "uniform values"}});
    request.mutable_source()->mutable_live_map()->clear_window_min();  // the whole live map
    request.mutable_source()->mutable_live_map()->clear_window_max();
    request.clear_eroi_semantic_values();
    status = Select(request, &response);
  }
  if (DependencyGone(status)) return Unavailable("SelectExplorationGoal", status);
  if (!status.ok()) {
    return absl::NotFoundError(
        absl::StrCat("no exploration goal from planning: ", status.error_message()));
  }
  return Eigen::Vector3d(response.goal().x(), response.goal().y(), pose.position.z());
}

}  // namespace semnav::reasoning
