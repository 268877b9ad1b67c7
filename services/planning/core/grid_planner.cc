#include "services/planning/core/grid_planner.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/planning/core/alternative_point.h"
#include "services/planning/core/inflation.h"
#include "services/planning/core/plan_failure.h"
#include "services/planning/core/reachability.h"

namespace semnav::planning {
namespace {

// Nearest free cell to `goal` within `radius` cells that is reachable.
std::optional<Cell> NearestFreeWithin(const PassabilityGrid& grid,
                                      const std::vector<uint8_t>& reachable, Cell goal,
                                      double radius) {
  const int r = static_cast<int>(std::floor(radius));
  std::optional<Cell> best;
  int best_d2 = 0;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const int d2 = dx * dx + dy * dy;
      const Cell c{goal.x + dx, goal.y + dy};
      if (d2 > radius * radius || !IsFree(grid, c.x, c.y) || reachable[grid.Index(c)] == 0) {
        continue;
      }
      if (!best || d2 < best_d2) {
        best = c;
        best_d2 = d2;
      }
    }
  }
  return best;
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

}  // namespace

absl::StatusOr<GridPath> GridPlanner::Search(const PassabilityGrid& grid, Cell start, Cell goal,
                                             const GridPlanRequest& request) {
  return request.use_jps ? jps_.Plan(grid, start, goal, request.limits)
                         : astar_.Plan(grid, start, goal, request.limits);
}

absl::StatusOr<GridPlanResult> GridPlanner::Plan(const GridPlanRequest& request) {
  const PassabilityGrid grid =
      InflateObstacles(request.free, request.robot_radius_m / request.resolution_m);
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
    const std::vector<uint8_t> reachable = ReachableFrom(grid, request.start);
    std::optional<Cell> replacement;
    if (request.goal_tolerance_m > 0.0) {
      replacement = NearestFreeWithin(grid, reachable, request.goal,
                                      request.goal_tolerance_m / request.resolution_m);
      result.goal_adjusted = replacement.has_value();
      if (replacement) result.adjustment_reason = "goal moved within goal_tolerance_m";
    }
    if (!replacement && request.first_sighting && grid.Contains(*request.first_sighting)) {
      replacement = FindAlternativePoint(grid, reachable, *request.first_sighting, request.goal);
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
