#include "clients/sim/core/nearest_goal_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace semnav::sim {

std::optional<NearestGoal> NearestReachableGoal(
    const GroundTruthGrid& grid, const Eigen::Vector2d& start,
    const std::function<bool(const Eigen::Vector2d&)>& is_goal) {
  const std::optional<Eigen::Vector2i> start_cell = grid.CellOf(start);
  if (!start_cell.has_value() || grid.at(start_cell->x(), start_cell->y()) != 0)
    return std::nullopt;
  const int sx = start_cell->x(), sy = start_cell->y();
  auto free = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < grid.width && y < grid.height && grid.at(x, y) == 0;
  };
  std::vector<double> cost(static_cast<size_t>(grid.width) * grid.height,
                           std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;  // cost in cells, cell index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  std::vector<int> parent(cost.size(), -1);
  cost[static_cast<size_t>(sy) * grid.width + sx] = 0.0;
  open.push({0.0, sy * grid.width + sx});
  while (!open.empty()) {
    const auto [c, index] = open.top();
    open.pop();
    if (c > cost[index]) continue;
    const int x = index % grid.width, y = index / grid.width;
    if (is_goal(grid.CellCentre(x, y))) {
      NearestGoal found{grid.CellCentre(x, y), c * grid.resolution, {}};
      for (int at = index; at >= 0; at = parent[at])
        found.path.push_back(grid.CellCentre(at % grid.width, at / grid.width));
      std::reverse(found.path.begin(), found.path.end());
      return found;
    }
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !free(x + dx, y + dy)) continue;
        if (dx != 0 && dy != 0 && !(free(x + dx, y) && free(x, y + dy))) continue;
        const double next = c + (dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0);
        const int n = (y + dy) * grid.width + x + dx;
        if (next < cost[n]) {
          cost[n] = next;
          parent[n] = index;
          open.push({next, n});
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace semnav::sim
