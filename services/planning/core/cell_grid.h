#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace semnav::planning {

// A grid cell: x = column, y = row, both 0-based.
struct Cell {
  int x = 0;
  int y = 0;
  friend bool operator==(const Cell&, const Cell&) = default;
};

// Row-major 2D grid of values; the one storage type every planner reads.
template <typename T>
class CellGrid {
 public:
  CellGrid() = default;
  CellGrid(int width, int height, T fill)
      : width_(width), height_(height), values_(static_cast<std::size_t>(width) * height, fill) {}

  int width() const { return width_; }
  int height() const { return height_; }
  int size() const { return width_ * height_; }
  bool Contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  bool Contains(Cell c) const { return Contains(c.x, c.y); }
  int Index(int x, int y) const { return y * width_ + x; }
  int Index(Cell c) const { return Index(c.x, c.y); }
  Cell CellAt(int index) const { return {index % width_, index / width_}; }

  T at(int x, int y) const { return values_[Index(x, y)]; }
  T at(Cell c) const { return values_[Index(c)]; }
  T& at(int x, int y) { return values_[Index(x, y)]; }
  T& at(Cell c) { return values_[Index(c)]; }
  const std::vector<T>& values() const { return values_; }
  std::vector<T>& values() { return values_; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<T> values_;
};

// 1 = traversable, 0 = blocked.
using PassabilityGrid = CellGrid<uint8_t>;

// True when (x, y) is inside the grid and traversable.
inline bool IsFree(const PassabilityGrid& grid, int x, int y) {
  return grid.Contains(x, y) && grid.at(x, y) != 0;
}

}  // namespace semnav::planning
