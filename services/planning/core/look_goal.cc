#include "services/planning/core/look_goal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "services/planning/core/alternative_point.h"

namespace semnav::planning {
namespace {

// Metres along the unit direction `dir` from `from` to where the ray leaves the rectangle
// [lo, hi] (from inside it); infinity along an axis the ray runs parallel to.
double ExitDistance(Point2 from, Point2 dir, Point2 lo, Point2 hi) {
  double t = std::numeric_limits<double>::infinity();
  if (dir.x > 0) t = std::min(t, (hi.x - from.x) / dir.x);
  if (dir.x < 0) t = std::min(t, (lo.x - from.x) / dir.x);
  if (dir.y > 0) t = std::min(t, (hi.y - from.y) / dir.y);
  if (dir.y < 0) t = std::min(t, (lo.y - from.y) / dir.y);
  return std::max(0.0, t);
}

bool Seen(const ExplorationGrid& grid, Cell c) {
  return grid.explored.Contains(c) && grid.explored.at(c) != 0;
}

}  // namespace

Point2 LookGoal(const ExplorationGrid& grid, Point2 robot, Point2 sighting,
                const LookGoalConfig& config) {
  const double length = std::hypot(sighting.x - robot.x, sighting.y - robot.y);
  if (length <= config.distance_m) return robot;
  const Point2 dir{(sighting.x - robot.x) / length, (sighting.y - robot.y) / length};
  const auto at = [&](double along) {
    return Point2{robot.x + dir.x * along, robot.y + dir.y * along};
  };
  const double straight = length - config.distance_m;
  // The cells of the line to the sighting, as far as the grid goes (unseen beyond): a far
  // sighting costs no more than the grid's size.
  const double res = grid.resolution_m;
  const Point2 lo{grid.origin_x, grid.origin_y};
  const Point2 hi{grid.origin_x + grid.explored.width() * res,
                  grid.origin_y + grid.explored.height() * res};
  const double walk = std::min(length, ExitDistance(robot, dir, lo, hi));
  const Cell start = grid.CellOf(robot);
  std::vector<double> blocked;  // along the line, metres (cell centres)
  std::vector<double> free;
  for (const Cell& c : LineCells(start, grid.CellOf(at(walk)))) {
    // The robot's own cell is not in front of it (mapping may mark a wall it stands beside).
    if (c == start) continue;
    const Point2 centre = grid.CentreOf(c);
    const double along = (centre.x - robot.x) * dir.x + (centre.y - robot.y) * dir.y;
    if (Seen(grid, c)) (IsFree(grid.free, c.x, c.y) ? free : blocked).push_back(along);
  }
  // A blocked cell is kept clear of by the clearance plus half its diagonal (where the line may
  // enter it).
  const double keep = config.clearance_m + res * std::numbers::sqrt2 / 2.0;
  const auto clear_of_blocked = [&](double along) {
    return std::none_of(blocked.begin(), blocked.end(),
                        [&](double b) { return std::abs(b - along) < keep; });
  };
  const bool blocked_before =
      std::any_of(blocked.begin(), blocked.end(), [&](double b) { return b < straight + keep; });
  if (!blocked_before) return at(straight);
  const Cell straight_cell = grid.CellOf(at(straight));
  if (Seen(grid, straight_cell) && IsFree(grid.free, straight_cell.x, straight_cell.y) &&
      clear_of_blocked(straight)) {
    return at(straight);
  }
  std::optional<double> best;
  for (double along : free) {
    if (along <= 0.0 || !clear_of_blocked(along)) continue;
    if (!best || std::abs(along - straight) < std::abs(*best - straight)) best = along;
  }
  return best ? at(*best) : robot;
}

}  // namespace semnav::planning
