#include "services/planning/core/straight_jump_table.h"

namespace semnav::planning {
namespace {

int DirectionOf(int dx, int dy) {
  if (dx != 0) return dx > 0 ? 0 : 1;
  return dy > 0 ? 2 : 3;
}

// run at a cell from `next`, the run at the following cell along the move
// (written for conditional moves rather than branches: the table build is
// the cold query's largest cost).
inline int32_t Extend(uint8_t next_open, uint8_t next_event, int32_t next) {
  const int32_t continued = next > 0 ? next + 1 : next - 1;
  const int32_t run = next_event != 0 ? 1 : continued;
  return next_open != 0 ? run : 0;
}

}  // namespace

void StraightJumpTable::Build(int width, int height, const std::vector<uint8_t>& blocked,
                              const std::vector<uint8_t>& stop) {
  width_ = width;
  height_ = height;
  if (width == 0 || height == 0) return;
  // Open cells with a one-cell closed border, so neighbour tests need no
  // bounds checks.
  const int pw = width + 2;
  std::vector<uint8_t> open(static_cast<size_t>(pw) * (height + 2), 0);
  for (int y = 0; y < height; ++y) {
    const uint8_t* b = blocked.data() + static_cast<size_t>(y) * width;
    uint8_t* o = open.data() + static_cast<size_t>(y + 1) * pw + 1;
    for (int x = 0; x < width; ++x) o[x] = b[x] == 0;
  }
  // Event bits per cell, one per direction (+x, -x, +y, -y): entering the
  // cell along that direction ends a jump there, because it is a stop cell
  // or has a forced neighbour (a side cell open while the cell behind that
  // side cell, towards where the move came from, is closed).
  std::vector<uint8_t> events(static_cast<size_t>(width) * height, 0);
  for (int y = 0; y < height; ++y) {
    const uint8_t* o = open.data() + static_cast<size_t>(y + 1) * pw + 1;
    const uint8_t* up = o + pw;
    const uint8_t* down = o - pw;
    const uint8_t* s = stop.data() + static_cast<size_t>(y) * width;
    uint8_t* e = events.data() + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      // Cells are 0/1, so `a & (b ^ 1)` is "a open and b closed".
      const int east = (up[x] & (up[x - 1] ^ 1)) | (down[x] & (down[x - 1] ^ 1));
      const int west = (up[x] & (up[x + 1] ^ 1)) | (down[x] & (down[x + 1] ^ 1));
      const int north = (o[x + 1] & (down[x + 1] ^ 1)) | (o[x - 1] & (down[x - 1] ^ 1));
      const int south = (o[x + 1] & (up[x + 1] ^ 1)) | (o[x - 1] & (up[x - 1] ^ 1));
      e[x] =
          static_cast<uint8_t>((s[x] != 0 ? 15 : 0) | east | west << 1 | north << 2 | south << 3);
    }
  }
  for (std::unique_ptr<int32_t[]>& runs : runs_) {
    runs = std::make_unique_for_overwrite<int32_t[]>(static_cast<size_t>(width) * height);
  }
  for (int y = 0; y < height; ++y) {
    const uint8_t* o = open.data() + static_cast<size_t>(y + 1) * pw + 1;
    const uint8_t* e = events.data() + static_cast<size_t>(y) * width;
    int32_t* east = runs_[0].get() + static_cast<size_t>(y) * width;
    int32_t* west = runs_[1].get() + static_cast<size_t>(y) * width;
    int32_t next = 0;
    for (int x = width - 1; x >= 0; --x) {
      next = east[x] = x + 1 < width ? Extend(o[x + 1], e[x + 1] & 1, next) : 0;
    }
    next = 0;
    for (int x = 0; x < width; ++x) {
      next = west[x] = x > 0 ? Extend(o[x - 1], e[x - 1] & 2, next) : 0;
    }
  }
  // Vertical passes row by row: the previous row holds the next cells.
  for (int x = 0; x < width; ++x) runs_[2][static_cast<size_t>(height - 1) * width + x] = 0;
  for (int y = height - 2; y >= 0; --y) {
    const uint8_t* o = open.data() + static_cast<size_t>(y + 2) * pw + 1;  // row y + 1
    const uint8_t* e = events.data() + static_cast<size_t>(y + 1) * width;
    const int32_t* next = runs_[2].get() + static_cast<size_t>(y + 1) * width;
    int32_t* run = runs_[2].get() + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) run[x] = Extend(o[x], e[x] & 4, next[x]);
  }
  for (int x = 0; x < width; ++x) runs_[3][x] = 0;
  for (int y = 1; y < height; ++y) {
    const uint8_t* o = open.data() + static_cast<size_t>(y) * pw + 1;  // row y - 1
    const uint8_t* e = events.data() + static_cast<size_t>(y - 1) * width;
    const int32_t* next = runs_[3].get() + static_cast<size_t>(y - 1) * width;
    int32_t* run = runs_[3].get() + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) run[x] = Extend(o[x], e[x] & 8, next[x]);
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
