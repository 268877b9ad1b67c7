#include "services/planning/core/path_shortcut.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>

namespace semnav::planning {
namespace {

double ExtraAt(const PassabilityGrid& grid, const std::vector<float>& cost, Cell c) {
  return cost.empty() ? 0.0 : cost[static_cast<std::size_t>(grid.Index(c))];
}

// A*'s cost of one 8-connected step (astar.cc): length x (1 + mean extra of both cells).
double StepCost(const PassabilityGrid& grid, const std::vector<float>& cost, Cell a, Cell b) {
  const double length = (a.x != b.x && a.y != b.y) ? std::sqrt(2.0) : 1.0;
  return length * (1.0 + 0.5 * (ExtraAt(grid, cost, a) + ExtraAt(grid, cost, b)));
}

// Cost of the straight segment between the centres of a and b (each cell's share of its length
// x (1 + its extra)), or nullopt when it touches a blocked cell. Walks the cells in order
// (Amanatides-Woo); where the segment passes exactly through a corner, both side cells must be
// free.
std::optional<double> SegmentCost(const PassabilityGrid& grid, const std::vector<float>& cost,
                                  Cell a, Cell b) {
  const int dx = b.x - a.x, dy = b.y - a.y;
  const int step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
  const int nx = std::abs(dx), ny = std::abs(dy);
  const double length = std::hypot(dx, dy);
  Cell at = a;
  if (!IsFree(grid, at.x, at.y)) return std::nullopt;
  // Crossing the i-th vertical cell line happens at t = (2i+1) / (2 nx), the j-th horizontal one
  // at (2j+1) / (2 ny); compared in integers as (2i+1) ny vs (2j+1) nx.
  int ix = 0, iy = 0;
  double t_entered = 0.0, total = 0.0;
  while (ix < nx || iy < ny) {
    const long long cross_x = static_cast<long long>(2 * ix + 1) * ny;
    const long long cross_y = static_cast<long long>(2 * iy + 1) * nx;
    Cell next = at;
    double t = 0.0;
    if (iy >= ny || (ix < nx && cross_x < cross_y)) {
      next.x += step_x;
      t = (2.0 * ix + 1.0) / (2.0 * nx);
      ++ix;
    } else if (ix >= nx || cross_y < cross_x) {
      next.y += step_y;
      t = (2.0 * iy + 1.0) / (2.0 * ny);
      ++iy;
    } else {
      if (!IsFree(grid, at.x + step_x, at.y) || !IsFree(grid, at.x, at.y + step_y))
        return std::nullopt;
      next.x += step_x;
      next.y += step_y;
      t = (2.0 * ix + 1.0) / (2.0 * nx);
      ++ix;
      ++iy;
    }
    if (!IsFree(grid, next.x, next.y)) return std::nullopt;
    total += (t - t_entered) * length * (1.0 + ExtraAt(grid, cost, at));
    t_entered = t;
    at = next;
  }
  return total + (1.0 - t_entered) * length * (1.0 + ExtraAt(grid, cost, at));
}

}  // namespace

std::vector<Cell> ShortcutPath(const PassabilityGrid& grid,
                               const std::vector<float>& clearance_cost,
                               const std::vector<Cell>& cells) {
  if (cells.size() <= 2) return cells;
  // Tolerance for the rounding of the two sums, relative.
  constexpr double kSlack = 1e-6;
  std::vector<Cell> out{cells.front()};
  std::size_t anchor = 0;
  while (anchor + 1 < cells.size()) {
    std::size_t reach = anchor + 1;
    double run_cost = StepCost(grid, clearance_cost, cells[anchor], cells[reach]);
    for (std::size_t j = anchor + 2; j < cells.size(); ++j) {
      run_cost += StepCost(grid, clearance_cost, cells[j - 1], cells[j]);
      const std::optional<double> straight =
          SegmentCost(grid, clearance_cost, cells[anchor], cells[j]);
      if (!straight.has_value() || *straight > run_cost * (1.0 + kSlack)) break;
      reach = j;
    }
    out.push_back(cells[reach]);
    anchor = reach;
  }
  return out;
}

double PolylineLengthCells(const std::vector<Cell>& waypoints) {
  double length = 0.0;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    length += std::hypot(waypoints[i].x - waypoints[i - 1].x, waypoints[i].y - waypoints[i - 1].y);
  }
  return length;
}

}  // namespace semnav::planning
