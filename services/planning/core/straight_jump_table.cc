#include "services/planning/core/straight_jump_table.h"

namespace semnav::planning {
namespace {

int DirectionOf(int dx, int dy) {
  if (dx != 0) return dx > 0 ? 0 : 1;
  return dy > 0 ? 2 : 3;
}

}  // namespace

void StraightJumpTable::Build(int width, int height, const std::vector<uint8_t>& blocked,
                              const std::vector<uint8_t>& stop) {
  width_ = width;
  height_ = height;
  // Open cells with a one-cell closed border, so neighbour tests need no
  // bounds checks.
  const int pw = width + 2;
  open_.assign(static_cast<size_t>(pw) * (height + 2), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) open_[(y + 1) * pw + x + 1] = blocked[y * width + x] == 0;
  }
  auto open = [&](int x, int y) { return open_[(y + 1) * pw + x + 1] != 0; };
  // Event for a move along (dx, dy) entering (x, y): a stop cell, or a side
  // cell open while the cell behind it is closed (a forced neighbour).
  auto event = [&](int x, int y, int dx, int dy) {
    const int sx = dy;
    const int sy = dx;
    return stop[y * width + x] != 0 ||
           (open(x + sx, y + sy) && !open(x + sx - dx, y + sy - dy)) ||
           (open(x - sx, y - sy) && !open(x - sx - dx, y - sy - dy));
  };
  // run at (x, y) from the run at the next cell (nx, ny) along the move.
  auto fill = [&](int dir, int x, int y, int dx, int dy) {
    const int nx = x + dx;
    const int ny = y + dy;
    int32_t& run = runs_[dir][y * width + x];
    if (!open(nx, ny)) {
      run = 0;
    } else if (event(nx, ny, dx, dy)) {
      run = 1;
    } else {
      const int32_t next = runs_[dir][ny * width + nx];
      run = next > 0 ? next + 1 : next - 1;
    }
  };
  for (std::vector<int32_t>& runs : runs_) runs.resize(static_cast<size_t>(width) * height);
  // Every pass walks against its direction, row-major where possible.
  for (int y = 0; y < height; ++y) {
    for (int x = width - 1; x >= 0; --x) fill(0, x, y, 1, 0);
    for (int x = 0; x < width; ++x) fill(1, x, y, -1, 0);
  }
  for (int y = height - 1; y >= 0; --y) {
    for (int x = 0; x < width; ++x) fill(2, x, y, 0, 1);
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) fill(3, x, y, 0, -1);
  }
}

bool StraightJumpTable::Jump(Cell from, int dx, int dy, Cell goal, Cell* found) const {
  const int32_t run = runs_[DirectionOf(dx, dy)][from.y * width_ + from.x];
  const int reach = run > 0 ? run : -run;
  const int to_goal = dx != 0 ? (goal.x - from.x) * dx : (goal.y - from.y) * dy;
  const bool goal_on_line = dx != 0 ? goal.y == from.y : goal.x == from.x;
  if (goal_on_line && to_goal > 0 && to_goal <= reach) {
    *found = goal;
    return true;
  }
  if (run <= 0) return false;
  *found = {from.x + dx * run, from.y + dy * run};
  return true;
}

}  // namespace semnav::planning
