#include "services/planning/core/frontier.h"

#include "services/planning/core/distance_field.h"
#include "services/planning/core/grid_search_common.h"

namespace semnav::planning {
namespace {

bool IsFrontierCell(const CellGrid<uint8_t>& explored, const PassabilityGrid& free, int x, int y) {
  if (explored.at(x, y) == 0 || free.at(x, y) == 0) return false;
  for (int m = 0; m < 4; ++m) {
    const int nx = x + kMoveDx[m];
    const int ny = y + kMoveDy[m];
    if (explored.Contains(nx, ny) && explored.at(nx, ny) == 0) return true;
  }
  return false;
}

}  // namespace

std::vector<Frontier> ExtractFrontiers(const CellGrid<uint8_t>& explored,
                                       const PassabilityGrid& free, int min_cells) {
  CellGrid<uint8_t> is_frontier(explored.width(), explored.height(), 0);
  for (int y = 0; y < explored.height(); ++y) {
    for (int x = 0; x < explored.width(); ++x) {
      is_frontier.at(x, y) = IsFrontierCell(explored, free, x, y);
    }
  }
  std::vector<Frontier> frontiers;
  std::vector<Cell> stack;
  for (int start = 0; start < is_frontier.size(); ++start) {
    if (is_frontier.values()[start] == 0) continue;
    Frontier frontier;
    is_frontier.values()[start] = 0;
    stack.assign(1, is_frontier.CellAt(start));
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      frontier.cells.push_back(c);
      for (int m = 0; m < 8; ++m) {
        const Cell n{c.x + kMoveDx[m], c.y + kMoveDy[m]};
        if (is_frontier.Contains(n) && is_frontier.at(n) != 0) {
          is_frontier.at(n) = 0;
          stack.push_back(n);
        }
      }
    }
    if (static_cast<int>(frontier.cells.size()) < min_cells) continue;
    for (const Cell& c : frontier.cells) {
      frontier.centroid_x += c.x;
      frontier.centroid_y += c.y;
    }
    frontier.centroid_x /= frontier.cells.size();
    frontier.centroid_y /= frontier.cells.size();
    double best = kUnreachable;
    for (const Cell& c : frontier.cells) {
      const double dx = c.x - frontier.centroid_x;
      const double dy = c.y - frontier.centroid_y;
      if (dx * dx + dy * dy < best) {
        best = dx * dx + dy * dy;
        frontier.anchor = c;
      }
    }
    frontiers.push_back(std::move(frontier));
  }
  return frontiers;
}

std::optional<NearestFrontier> SelectNearestFrontier(const std::vector<Frontier>& frontiers,
                                                     const PassabilityGrid& free,
                                                     const std::vector<double>& distance) {
  std::optional<NearestFrontier> best;
  for (size_t f = 0; f < frontiers.size(); ++f) {
    for (const Cell& c : frontiers[f].cells) {
      const double d = distance[free.Index(c)];
      if (d == kUnreachable || (best && d >= best->distance_cells)) continue;
      best = NearestFrontier{static_cast<int>(f), c, d};
    }
  }
  return best;
}

}  // namespace semnav::planning
