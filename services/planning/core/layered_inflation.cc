#include "services/planning/core/layered_inflation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "services/planning/core/inflation.h"
#include "services/planning/core/nearest_cell.h"

namespace semnav::planning {
namespace {

// True when a 4-neighbour inside the grid holds a lower value: only such cells can raise a cell
// beyond what their neighbours raise (a cell within the radius of c is at least as close to
// the 4-neighbour of c towards it).
bool RaisesNeighbours(const LayeredGrid& grid, int x, int y) {
  const uint8_t v = grid.at(x, y);
  constexpr int kDx[] = {1, -1, 0, 0};
  constexpr int kDy[] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int nx = x + kDx[k];
    const int ny = y + kDy[k];
    if (grid.Contains(nx, ny) && grid.at(nx, ny) < v) return true;
  }
  return false;
}

}  // namespace

LayeredGrid InflateLayeredGrid(const LayeredGrid& grid, double radius_cells) {
  if (radius_cells <= 0.0) return grid;
  const std::vector<Cell> disc = DiscOffsets(radius_cells);
  LayeredGrid out = grid;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      const uint8_t v = grid.at(x, y);
      if (v == 0 || !RaisesNeighbours(grid, x, y)) continue;
      for (const Cell& d : disc) {
        if (!out.Contains(x + d.x, y + d.y)) continue;
        uint8_t& cell = out.at(x + d.x, y + d.y);
        cell = std::max(cell, v);
      }
    }
  }
  return out;
}

std::optional<Cell> NearestPassableCell(const LayeredGrid& grid, Cell start, double radius_cells) {
  return NearestCellWithin(start, radius_cells, [&](Cell c) { return Passable(grid, c.x, c.y); });
}

}  // namespace semnav::planning
