// Growing a grid to take in cells beyond its edges: a robot that stands just outside the map it
// drew (its own cell unseen at the start), or a goal in unseen space planned through.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// Cells a grid grows by on each edge.
struct Padding {
  int left = 0, right = 0, bottom = 0, top = 0;
  bool any() const { return left + right + bottom + top > 0; }
  // How far the padded-to cell lay beyond the grid, in cells (the diagonal of the two sides).
  double OutsideCells() const { return std::hypot(std::max(left, right), std::max(bottom, top)); }
};

// A padded grid holds at most this many cells, the budget of a grid in a request (8192 x 8192):
// a one-row grid of fine cells padded by a metre would otherwise need gigabytes.
inline constexpr int64_t kMaxPaddedCells = int64_t{1} << 26;

// Cells of a width x height grid grown by `pad`.
inline int64_t PaddedCells(int width, int height, const Padding& pad) {
  return (int64_t{width} + pad.left + pad.right) * (int64_t{height} + pad.bottom + pad.top);
}

// The padding a width x height grid needs to contain `c`.
inline Padding PaddingFor(int width, int height, Cell c) {
  return {std::max(0, -c.x), std::max(0, c.x - (width - 1)), std::max(0, -c.y),
          std::max(0, c.y - (height - 1))};
}

inline Padding Union(const Padding& a, const Padding& b) {
  return {std::max(a.left, b.left), std::max(a.right, b.right), std::max(a.bottom, b.bottom),
          std::max(a.top, b.top)};
}

// `grid` grown by `pad`, new cells set to `fill`; an empty grid stays empty.
template <typename T>
CellGrid<T> Padded(const CellGrid<T>& grid, const Padding& pad, T fill) {
  if (grid.size() == 0) return grid;
  CellGrid<T> out(grid.width() + pad.left + pad.right, grid.height() + pad.bottom + pad.top, fill);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) out.at(x + pad.left, y + pad.bottom) = grid.at(x, y);
  }
  return out;
}

// A cell of the grid before padding in the padded grid's indices.
inline Cell IntoPadded(Cell c, const Padding& pad) { return {c.x + pad.left, c.y + pad.bottom}; }
// A cell of the padded grid in the indices before padding.
inline Cell OutOfPadded(Cell c, const Padding& pad) { return {c.x - pad.left, c.y - pad.bottom}; }

}  // namespace semnav::planning
