#include "services/planning/core/landmark_heuristic.h"

#include <limits>

#include "services/planning/core/grid_search_common.h"
#include "services/planning/core/octile.h"

namespace semnav::planning {
namespace {

// Walks the diagonal in from a corner to the first passable cell.
bool CornerLandmark(const LayeredGrid& grid, int corner, Cell* found) {
  const int dx = corner & 1 ? -1 : 1;
  const int dy = corner & 2 ? -1 : 1;
  Cell c{dx > 0 ? 0 : grid.width() - 1, dy > 0 ? 0 : grid.height() - 1};
  for (; grid.Contains(c); c = {c.x + dx, c.y + dy}) {
    if (Passable(grid, c.x, c.y)) {
      *found = c;
      return true;
    }
  }
  return false;
}

// Exact costs from `source` to every cell over the search's unit moves
// (infinite where unreachable). The moves have only 4 costs (roll or fly,
// straight or diagonal), so 4 FIFO queues replace Dijkstra's heap: cells
// settle in nondecreasing cost, so each queue receives nondecreasing keys
// and its front is its minimum (3x fewer instructions than the heap).
std::vector<double> CostsFrom(const LayeredGrid& grid, Cell source, const StepCosts& costs) {
  const double step[4] = {costs.roll, costs.roll * kSqrt2, costs.fly, costs.fly * kSqrt2};
  struct Item {
    double cost;
    int cell;
  };
  std::vector<Item> queues[4];
  size_t heads[4] = {0, 0, 0, 0};
  std::vector<double> dist(grid.size(), std::numeric_limits<double>::infinity());
  std::vector<uint8_t> settled(grid.size(), 0);
  dist[grid.Index(source)] = 0.0;
  queues[0].push_back({0.0, grid.Index(source)});
  while (true) {
    int best = -1;
    for (int k = 0; k < 4; ++k) {
      if (heads[k] == queues[k].size()) continue;
      if (best < 0 || queues[k][heads[k]].cost < queues[best][heads[best]].cost) best = k;
    }
    if (best < 0) break;
    const Item item = queues[best][heads[best]++];
    if (settled[item.cell] != 0) continue;  // a cheaper copy came first
    settled[item.cell] = 1;
    ForEachMove(grid, grid.CellAt(item.cell), [&](Cell n, MotionMode mode, double length) {
      const int next = grid.Index(n);
      const int k = (mode == MotionMode::kFlying ? 2 : 0) + (length > 1.0 ? 1 : 0);
      const double cost = item.cost + step[k];
      if (cost < dist[next]) {
        dist[next] = cost;
        queues[k].push_back({cost, next});
      }
    });
  }
  return dist;
}

}  // namespace

LandmarkHeuristic::LandmarkHeuristic(const LayeredGrid& grid, const StepCosts& costs)
    : costs_(costs) {
  std::vector<Cell> cells;
  for (int corner = 0; corner < kMaxLandmarks; ++corner) {
    Cell c;
    const bool found = CornerLandmark(grid, corner, &c);
    if (found && std::find(cells.begin(), cells.end(), c) == cells.end()) cells.push_back(c);
  }
  count_ = static_cast<int>(cells.size());
  dist_.assign(static_cast<size_t>(grid.size()) * count_, std::numeric_limits<double>::infinity());
  for (int l = 0; l < count_; ++l) {
    const std::vector<double> costs_from = CostsFrom(grid, cells[l], costs_);
    for (int cell = 0; cell < grid.size(); ++cell) {
      dist_[static_cast<size_t>(cell) * count_ + l] = costs_from[cell];
    }
  }
}

LandmarkHeuristic::ToGoal LandmarkHeuristic::Towards(int goal_cell) const {
  ToGoal bound;
  bound.dist_ = dist_.data();
  bound.count_ = count_;
  std::copy_n(dist_.data() + static_cast<size_t>(goal_cell) * count_, count_, bound.goal_.begin());
  return bound;
}

}  // namespace semnav::planning
