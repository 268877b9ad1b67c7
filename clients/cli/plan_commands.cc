// plan path: the planning service's PlanPath on the live map or on a text grid; prints length,
// energy and the fly/roll split.
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "clients/cli/core/args.h"
#include "clients/cli/core/exit_codes.h"
#include "clients/cli/core/table.h"
#include "clients/cli/core/text_grid.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"

namespace semnav::cli {
namespace {

namespace api = ::semnav::planning::v1;

const std::vector<std::string> kPlannerNames = {"jps", "astar", "jump-astar"};
const api::PlannerKind kPlanners[] = {api::PLANNER_KIND_JPS, api::PLANNER_KIND_ASTAR,
                                      api::PLANNER_KIND_JUMP_ASTAR};

absl::Status SetPoint(const Invocation& invocation, const std::string& flag,
                      common::v1::Pose2D* pose) {
  absl::StatusOr<Point2> point = ParsePoint(flag, invocation.Flag(flag));
  if (!point.ok()) return point.status();
  pose->set_x(point->x);
  pose->set_y(point->y);
  return absl::OkStatus();
}

// The inline grid of --grid FILE with --resolution and --origin.
absl::Status SetTextGrid(const Invocation& invocation, common::v1::GridMap* grid) {
  std::ifstream in(invocation.Flag("grid"));
  if (!in)
    return absl::InvalidArgumentError(
        absl::StrCat("--grid: cannot read '", invocation.Flag("grid"), "'"));
  std::stringstream text;
  text << in.rdbuf();
  absl::StatusOr<TextGrid> parsed = ParseTextGrid(text.str());
  if (!parsed.ok())
    return absl::InvalidArgumentError(absl::StrCat("--grid: ", parsed.status().message()));
  absl::StatusOr<double> resolution =
      ParseNumber("resolution", invocation.Flag("resolution", "1"), 1e-6);
  if (!resolution.ok()) return resolution.status();
  absl::StatusOr<Point2> origin = ParsePoint("origin", invocation.Flag("origin", "0,0"));
  if (!origin.ok()) return origin.status();
  grid->set_resolution(*resolution);
  grid->mutable_origin()->set_x(origin->x);
  grid->mutable_origin()->set_y(origin->y);
  grid->set_width(parsed->width);
  grid->set_height(parsed->height);
  common::v1::GridLayer* layer = grid->add_layers();
  layer->set_kind(common::v1::GRID_LAYER_KIND_HIERARCHICAL);
  layer->set_data(std::string(parsed->cells.begin(), parsed->cells.end()));
  return absl::OkStatus();
}

absl::StatusOr<api::PlanPathRequest> BuildRequest(const Invocation& invocation) {
  if (!invocation.Has("from") || !invocation.Has("to"))
    return absl::InvalidArgumentError("plan path needs --from and --to");
  api::PlanPathRequest request;
  if (absl::Status s = SetPoint(invocation, "from", request.mutable_start()); !s.ok()) return s;
  if (absl::Status s = SetPoint(invocation, "to", request.mutable_goal()); !s.ok()) return s;
  absl::StatusOr<std::size_t> planner =
      ParseChoice("planner", invocation.Flag("planner", "jps"), kPlannerNames);
  if (!planner.ok()) return planner.status();
  request.set_planner(kPlanners[*planner]);
  if (invocation.Has("grid")) {
    if (absl::Status s = SetTextGrid(invocation, request.mutable_source()->mutable_grid()); !s.ok())
      return s;
  } else {
    api::LiveMapGrid* live = request.mutable_source()->mutable_live_map();
    if (invocation.Has("window-min") != invocation.Has("window-max")) {
      return absl::InvalidArgumentError("--window-min and --window-max go together");
    }
    if (invocation.Has("window-min")) {
      if (absl::Status s = SetPoint(invocation, "window-min", live->mutable_window_min()); !s.ok())
        return s;
      if (absl::Status s = SetPoint(invocation, "window-max", live->mutable_window_max()); !s.ok())
        return s;
    }
  }
  const std::pair<const char*, std::function<void(double)>> numbers[] = {
      {"robot-radius", [&](double v) { request.set_robot_radius_m(v); }},
      {"goal-tolerance", [&](double v) { request.set_goal_tolerance_m(v); }},
      {"alpha", [&](double v) { request.mutable_multimodal()->set_alpha(v); }},
      {"beta", [&](double v) { request.mutable_multimodal()->set_beta(v); }}};
  for (const auto& [flag, set] : numbers) {
    if (!invocation.Has(flag)) continue;
    absl::StatusOr<double> value = ParseNumber(flag, invocation.Flag(flag), 0.0);
    if (!value.ok()) return value.status();
    set(*value);
  }
  return request;
}

std::string Describe(const api::PlanPathResponse& path, bool waypoints) {
  std::string out = absl::StrCat(
      "length ", FormatFixed(path.length_m(), 2), " m  (roll ", FormatFixed(path.roll_m(), 2),
      " m, fly ", FormatFixed(path.fly_m(), 2), " m, ", path.mode_switches(),
      " mode switches)  energy ", FormatFixed(path.energy_j(), 1), " J\n");
  absl::StrAppend(&out, path.path_size(), " waypoints to (",
                  FormatFixed(path.planned_goal().x(), 2), ", ",
                  FormatFixed(path.planned_goal().y(), 2), ")");
  if (!path.adjustment_reason().empty())
    absl::StrAppend(&out, "  goal changed: ", path.adjustment_reason());
  absl::StrAppend(&out, "\n", path.expansions(), " expansions in ",
                  FormatFixed(path.planning_time_ms(), 2), " ms, map revision ",
                  path.map_revision(), "\n\n");
  Table segments({"MODE", "FROM", "TO", "LENGTH_M", "ENERGY_J"});
  for (const api::PathSegment& segment : path.segments()) {
    segments.AddRow({ShortEnumName(api::MotionMode_Name(segment.mode()), "MOTION_MODE_"),
                     std::to_string(segment.first_point()), std::to_string(segment.last_point()),
                     FormatFixed(segment.length_m(), 2), FormatFixed(segment.energy_j(), 1)});
  }
  absl::StrAppend(&out, segments.Render());
  if (waypoints) {
    Table points({"#", "X", "Y", "YAW"});
    for (int i = 0; i < path.path_size(); ++i) {
      points.AddRow({std::to_string(i), FormatFixed(path.path(i).x(), 2),
                     FormatFixed(path.path(i).y(), 2), FormatFixed(path.path(i).yaw(), 3)});
    }
    absl::StrAppend(&out, "\n", points.Render());
  }
  return out;
}

int Plan(const Invocation& invocation) {
  absl::StatusOr<api::PlanPathRequest> request = BuildRequest(invocation);
  if (!request.ok()) return UsageError(std::string(request.status().message()));
  return WithStub<api::PlanningService>(
      invocation, Service::kPlanning, [&](api::PlanningService::Stub& stub) {
        api::PlanPathResponse response;
        absl::Status status =
            CallUnary(invocation, stub, &api::PlanningService::Stub::PlanPath, *request, &response);
        if (!status.ok()) {
          if (std::optional<api::PlanFailureDetail> detail =
                  GetDetail<api::PlanFailureDetail>(status)) {
            std::cerr << "plan failed: "
                      << ShortEnumName(api::PlanFailureReason_Name(detail->reason()),
                                       "PLAN_FAILURE_REASON_")
                      << " (start cell " << detail->start_column() << "," << detail->start_row()
                      << ", goal cell " << detail->goal_column() << "," << detail->goal_row() << ")"
                      << std::endl;
          }
          return Fail(status);
        }
        if (invocation.json()) {
          PrintJson(response);
        } else {
          std::cout << Describe(response, invocation.Has("waypoints"));
        }
        return ToInt(ExitCode::kOk);
      });
}

}  // namespace

std::vector<Command> PlanCommands() {
  return {
      {"plan",
       "path",
       "",
       "plan a path and print its length, energy and roll/fly split",
       Service::kPlanning,
       {{"from", "X,Y", "start, map frame, metres (required)"},
        {"to", "X,Y", "goal, map frame, metres (required)"},
        {"planner", "NAME", "jps (default), astar, or jump-astar (multi-modal roll/fly)"},
        {"grid", "FILE",
         "plan on this text grid (Moving AI .map or rows of . # 1-9 ?) instead of the live map"},
        {"resolution", "METRES", "cell size of --grid (default 1)"},
        {"origin", "X,Y", "map position of --grid's cell (0,0) corner (default 0,0)"},
        {"window-min", "X,Y", "live map: lower-left corner of the window (default whole map)"},
        {"window-max", "X,Y", "live map: upper-right corner of the window"},
        {"robot-radius", "METRES", "footprint inflation of the 2D planners (default 0)"},
        {"goal-tolerance", "METRES", "an occupied goal may move this far (default 0)"},
        {"alpha", "W", "jump-astar distance weight (default: service config)"},
        {"beta", "W", "jump-astar energy weight (default: service config)"},
        {"waypoints", "", "also print every waypoint"}},
       Plan,
       0},
  };
}

}  // namespace semnav::cli
