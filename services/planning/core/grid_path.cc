#include "services/planning/core/grid_path.h"

#include <cstdlib>

namespace semnav::planning {

std::vector<Cell> ExpandWaypoints(const std::vector<Cell>& waypoints) {
  std::vector<Cell> cells;
  if (waypoints.empty()) return cells;
  cells.push_back(waypoints.front());
  for (size_t i = 1; i < waypoints.size(); ++i) {
    Cell at = waypoints[i - 1];
    const Cell to = waypoints[i];
    const int sx = (to.x > at.x) - (to.x < at.x);
    const int sy = (to.y > at.y) - (to.y < at.y);
    while (!(at == to)) {
      // Diagonal first while both axes differ, then straight: the shape JPS
      // and A* runs take between two waypoints.
      if (at.x != to.x) at.x += sx;
      if (at.y != to.y) at.y += sy;
      cells.push_back(at);
    }
  }
  return cells;
}

}  // namespace semnav::planning
