#include "services/planning/core/grid_planner.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/planning/core/alternative_point.h"
#include "services/planning/core/distance_field.h"
#include "services/planning/core/grid_padding.h"
#include "services/planning/core/inflation.h"
#include "services/planning/core/nearest_cell.h"
#include "services/planning/core/octile.h"
#include "services/planning/core/path_shortcut.h"
#include "services/planning/core/plan_failure.h"
#include "services/planning/core/reachability.h"

namespace semnav::planning {
namespace {

// Nearest free cell to `goal` within `radius` cells that is reachable.
std::optional<Cell> NearestFreeWithin(const PassabilityGrid& grid,
                                      const std::vector<uint8_t>& reachable, Cell goal,
                                      double radius) {
  return NearestCellWithin(goal, radius, [&](Cell c) {
    return IsFree(grid, c.x, c.y) && reachable[grid.Index(c)] != 0;
  });
}

// The goal within `radius` cells of an occupied `goal`: the free cell nearest it among those the
// robot reaches without a detour, at most 2 x radius longer than the way to the first of them
// (ties: the shorter way). The nearest free cell alone can lie beyond a wall the goal stands
// against, reached round through a door (generated office_04's microwave: a 51 s way round, and
// a stop scored outside the success region; 18 s and found with this rule).
std::optional<Cell> ToleranceGoal(const PassabilityGrid& grid, Cell start, Cell goal,
                                  double radius) {
  const std::vector<double> way = OctileDistanceField(grid, start);
  const auto reachable_free = [&](Cell c) {
    return IsFree(grid, c.x, c.y) && way[grid.Index(c)] != kUnreachable;
  };
  double shortest = kUnreachable;
  for (const Cell& o : DiscOffsets(radius)) {
    const Cell c{goal.x + o.x, goal.y + o.y};
    if (reachable_free(c)) shortest = std::min(shortest, way[grid.Index(c)]);
  }
  if (shortest == kUnreachable) return std::nullopt;
  const double longest = shortest + 2.0 * radius;
  return NearestCellWithin(
      goal, radius, [&](Cell c) { return reachable_free(c) && way[grid.Index(c)] <= longest; },
      [&](Cell c) { return std::lround(way[grid.Index(c)] * 1000.0); });
}

// Free cells restricted to obstacle probability <= max_percent (start and
// goal stay as they are, so a robot standing near an obstacle can leave).
PassabilityGrid WithProbabilityLimit(const PassabilityGrid& free,
                                     const CellGrid<uint8_t>& probability, int max_percent,
                                     Cell start, Cell goal) {
  PassabilityGrid out = free;
  for (int i = 0; i < out.size(); ++i) {
    if (probability.values()[i] > max_percent) out.values()[i] = 0;
  }
  if (free.Contains(start)) out.at(start) = free.at(start);
  if (free.Contains(goal)) out.at(goal) = free.at(goal);
  return out;
}

// Nearest free cell to `start` within `radius` cells (Euclidean; ties: the one nearer `goal`,
// then the first in row order).
std::optional<Cell> NearestFreeCell(const PassabilityGrid& grid, Cell start, Cell goal,
                                    double radius) {
  return NearestCellWithin(
      start, radius, [&](Cell c) { return IsFree(grid, c.x, c.y); },
      [&](Cell c) {
        return long{c.x - goal.x} * (c.x - goal.x) + long{c.y - goal.y} * (c.y - goal.y);
      });
}

}  // namespace

absl::StatusOr<GridPath> GridPlanner::Search(const PassabilityGrid& grid, Cell start, Cell goal,
                                             const GridPlanRequest& request) {
  if (clearance_cost_ != nullptr) {
    absl::StatusOr<GridPath> path = astar_.Plan(grid, start, goal, request.limits, clearance_cost_);
    if (path.ok()) {
      path->waypoints = ShortcutPath(grid, *clearance_cost_, path->waypoints);
      path->length_cells = PolylineLengthCells(path->waypoints);
    }
    return path;
  }
  return request.use_jps ? jps_.Plan(grid, start, goal, request.limits)
                         : astar_.Plan(grid, start, goal, request.limits);
}

absl::StatusOr<GridPlanResult> GridPlanner::Plan(const GridPlanRequest& original) {
  GridPlanRequest request = original;
  std::optional<Cell> requested_goal;
  const double goal_outside_m =
      std::hypot(std::clamp(request.goal.x, 0, request.free.width() - 1) - request.goal.x,
                 std::clamp(request.goal.y, 0, request.free.height() - 1) - request.goal.y) *
      request.resolution_m;
  if (!request.free.Contains(request.goal) && request.outside_is_free &&
      goal_outside_m <= config_.max_free_goal_outside_m) {
    return PlanPadded(request, /*pad_to_goal=*/true);
  }
  if (!request.free.Contains(request.goal)) {
    // A target seen just past the map's edge: plan to the edge cell nearest it, which the map
    // then grows past as the robot arrives.
    const Cell edge{std::clamp(request.goal.x, 0, request.free.width() - 1),
                    std::clamp(request.goal.y, 0, request.free.height() - 1)};
    const double outside_m =
        std::hypot(edge.x - request.goal.x, edge.y - request.goal.y) * request.resolution_m;
    if (outside_m > config_.max_goal_outside_m) {
      return InvalidField(
          "goal", absl::StrCat("goal (", request.goal.x, ", ", request.goal.y, ") is outside the ",
                               request.free.width(), " x ", request.free.height(), " grid"));
    }
    requested_goal = request.goal;
    request.goal = edge;
  }
  absl::StatusOr<GridPlanResult> result = PlanPadded(request, /*pad_to_goal=*/false);
  if (result.ok() && requested_goal) {
    result->goal_adjusted = true;
    result->adjustment_reason =
        result->adjustment_reason.empty()
            ? "goal outside the grid moved to the grid's edge"
            : absl::StrCat("goal outside the grid moved to the grid's edge; ",
                           result->adjustment_reason);
  }
  return result;
}

absl::StatusOr<GridPlanResult> GridPlanner::PlanPadded(const GridPlanRequest& request,
                                                       bool pad_to_goal) {
  const int width = request.free.width();
  const int height = request.free.height();
  const Padding to_start = PaddingFor(width, height, request.start);
  const Padding pad =
      pad_to_goal ? Union(to_start, PaddingFor(width, height, request.goal)) : to_start;
  if (!pad.any()) return PlanInside(request);
  const double outside_m = to_start.OutsideCells() * request.resolution_m;
  if (outside_m > config_.max_start_outside_m) {
    return InvalidField(
        "start", absl::StrCat("start (", request.start.x, ", ", request.start.y, ") is ", outside_m,
                              " m outside the ", request.free.width(), " x ", request.free.height(),
                              " grid (max_start_outside_m ", config_.max_start_outside_m, ")"));
  }
  if (PaddedCells(width, height, pad) > kMaxPaddedCells) {
    return InvalidField(
        pad_to_goal ? "goal" : "start",
        absl::StrCat("the grid padded to it would exceed ", kMaxPaddedCells, " cells"));
  }
  // The robot stands there, so the strip between it and the map is taken as free; so is the
  // strip out to a goal beyond the map when outside counts as free.
  GridPlanRequest padded = request;
  padded.prepared = nullptr;  // prepared for the grid before padding
  padded.free = Padded<uint8_t>(request.free, pad, 1);
  padded.obstacle_probability = Padded<uint8_t>(request.obstacle_probability, pad, 0);
  padded.start = IntoPadded(request.start, pad);
  padded.goal = IntoPadded(request.goal, pad);
  if (padded.first_sighting) padded.first_sighting = IntoPadded(*request.first_sighting, pad);
  absl::StatusOr<GridPlanResult> result = PlanInside(padded);
  if (!result.ok()) return result;
  for (Cell& c : result->path.waypoints) c = OutOfPadded(c, pad);
  result->planned_goal = OutOfPadded(result->planned_goal, pad);
  result->planned_start = OutOfPadded(result->planned_start, pad);
  result->grid_padded = true;
  return result;
}

PreparedFootprint GridPlanner::Prepare(const PassabilityGrid& free, double resolution_m,
                                       double robot_radius_m, bool keep_clearance) const {
  PreparedFootprint prepared;
  prepared.robot_radius_m = robot_radius_m;
  prepared.with_clearance = keep_clearance;
  prepared.inflated = InflateObstacles(free, robot_radius_m / resolution_m);
  if (keep_clearance) {
    prepared.clearance_cost = ClearanceCost(prepared.inflated, resolution_m, config_.clearance);
  }
  return prepared;
}

absl::StatusOr<GridPlanResult> GridPlanner::PlanInside(const GridPlanRequest& original) {
  std::shared_ptr<const PreparedFootprint> prepared = original.prepared;
  const bool fits = prepared != nullptr && prepared->robot_radius_m == original.robot_radius_m &&
                    prepared->with_clearance == original.keep_clearance &&
                    prepared->inflated.width() == original.free.width() &&
                    prepared->inflated.height() == original.free.height();
  if (!fits) {
    prepared = std::make_shared<const PreparedFootprint>(Prepare(
        original.free, original.resolution_m, original.robot_radius_m, original.keep_clearance));
  }
  const PassabilityGrid& grid = prepared->inflated;
  GridPlanRequest request = original;
  if (grid.Contains(original.start) && grid.at(original.start) == 0 &&
      config_.start_snap_radius_m > 0.0) {
    const std::optional<Cell> free = NearestFreeCell(
        grid, original.start, original.goal, config_.start_snap_radius_m / original.resolution_m);
    if (!free) {
      return MakePlanFailure(PlanFailure::kStartOccupied,
                             absl::StrCat("start (", original.start.x, ", ", original.start.y,
                                          ") is occupied and no free cell lies within "
                                          "start_snap_radius_m ",
                                          config_.start_snap_radius_m));
    }
    request.start = *free;
  }
  clearance_cost_ = request.keep_clearance && !prepared->clearance_cost.empty()
                        ? &prepared->clearance_cost
                        : nullptr;  // no cost (clearance 0): JPS, as without clearance
  absl::StatusOr<GridPlanResult> result = PlanStages(grid, request);
  if (PlanFailureOf(result.status()) == PlanFailure::kNoPath && config_.start_snap_radius_m > 0.0 &&
      IsFree(grid, request.goal.x, request.goal.y)) {
    // Boxed in: the robot stands on a free island the inflation cut off (after a collision,
    // next to a counter). Leave it for the nearest cell within the snap radius the goal can be
    // reached from.
    const std::vector<uint8_t> to_goal = ReachableFrom(grid, request.goal);
    const std::optional<Cell> exit = NearestFreeWithin(
        grid, to_goal, original.start, config_.start_snap_radius_m / original.resolution_m);
    if (exit && !(*exit == request.start)) {
      request.start = *exit;
      result = PlanStages(grid, request);
    }
  }
  clearance_cost_ = nullptr;
  if (!result.ok()) return result;
  result->planned_start = request.start;
  if (!(request.start == original.start)) {
    // The path begins where the robot stands, then leaves the inflated zone.
    result->start_adjusted = true;
    result->path.waypoints.insert(result->path.waypoints.begin(), original.start);
    result->path.length_cells += OctileDistance(original.start, request.start);
  }
  return result;
}

absl::StatusOr<GridPlanResult> GridPlanner::PlanStages(const PassabilityGrid& grid,
                                                       const GridPlanRequest& request) {
  if (request.obstacle_probability.size() == 0) return PlanOn(grid, request);
  // Stage 1: zero-probability cells only; stage 2: low-probability cells too.
  absl::StatusOr<GridPlanResult> zero = PlanOn(
      WithProbabilityLimit(grid, request.obstacle_probability, 0, request.start, request.goal),
      request);
  const std::optional<PlanFailure> failure = PlanFailureOf(zero.status());
  if (zero.ok() || failure == PlanFailure::kTimeout || failure == PlanFailure::kCancelled ||
      !failure) {
    return zero;
  }
  absl::StatusOr<GridPlanResult> low =
      PlanOn(WithProbabilityLimit(grid, request.obstacle_probability,
                                  config_.max_low_probability_percent, request.start, request.goal),
             request);
  if (low.ok()) low->low_probability_cells_used = true;
  return low;
}

absl::StatusOr<GridPlanResult> GridPlanner::PlanOn(const PassabilityGrid& grid,
                                                   const GridPlanRequest& request) {
  GridPlanResult result;
  result.planned_goal = request.goal;
  absl::StatusOr<GridPath> path = Search(grid, request.start, request.goal, request);
  const std::optional<PlanFailure> failure = PlanFailureOf(path.status());
  const bool goal_problem =
      failure == PlanFailure::kGoalOccupied || failure == PlanFailure::kNoPath;
  const bool may_replace = request.goal_tolerance_m > 0.0 || request.first_sighting.has_value();
  if (!path.ok() && goal_problem && may_replace) {
    std::optional<Cell> replacement;
    if (request.goal_tolerance_m > 0.0) {
      replacement = ToleranceGoal(grid, request.start, request.goal,
                                  request.goal_tolerance_m / request.resolution_m);
      result.goal_adjusted = replacement.has_value();
      if (replacement) result.adjustment_reason = "goal moved within goal_tolerance_m";
    }
    if (!replacement && request.first_sighting && grid.Contains(*request.first_sighting)) {
      replacement = FindAlternativePoint(grid, ReachableFrom(grid, request.start),
                                         *request.first_sighting, request.goal);
      result.alternative_used = replacement.has_value();
      if (replacement) {
        result.adjustment_reason = absl::StrCat(
            failure == PlanFailure::kGoalOccupied ? "goal is inside an obstacle"
                                                  : "goal is enclosed by obstacles",
            "; planned to the nearest free reachable point on the line from the first sighting");
      }
    }
    if (replacement) {
      result.planned_goal = *replacement;
      path = Search(grid, request.start, *replacement, request);
    }
  }
  if (!path.ok()) return path.status();
  result.path = *std::move(path);
  return result;
}

}  // namespace semnav::planning
