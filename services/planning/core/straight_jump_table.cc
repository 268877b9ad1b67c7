#include "services/planning/core/straight_jump_table.h"

#include <utility>

namespace semnav::planning {

void StraightJumpTable::Lines::Build(BitRows line_open, const BitRows& stop) {
  open = std::move(line_open);
  const int lines = open.rows();
  const int words = open.words_per_row();
  ends_forward = BitRows(lines, open.columns());
  ends_backward = BitRows(lines, open.columns());
  for (int r = 0; r < lines; ++r) {
    const uint64_t* stops = stop.row(r);
    const uint64_t* cells = open.row(r);
    uint64_t* forward = ends_forward.row(r);
    uint64_t* backward = ends_backward.row(r);
    for (int w = 0; w < words; ++w) {
      uint64_t fwd = stops[w];
      uint64_t bwd = stops[w];
      // A side line's cell open while its neighbour towards where the move
      // came from is closed forces a turn there.
      for (int side : {r - 1, r + 1}) {
        if (side < 0 || side >= lines) continue;
        const uint64_t s = open.row(side)[w];
        fwd |= s & ~open.PreviousColumnWord(side, w);
        bwd |= s & ~open.NextColumnWord(side, w);
      }
      // Padding columns are not open, so scans stop at the line's end.
      forward[w] = fwd | ~cells[w];
      backward[w] = bwd | ~cells[w];
    }
  }
}

void StraightJumpTable::Build(const BitRows& open, const BitRows& stop) {
  rows_.Build(open, stop);
  columns_.Build(open.Transposed(), stop.Transposed());
}

bool StraightJumpTable::Jump(Cell from, int dx, int dy, Cell goal, Cell* found) const {
  const bool along_x = dy == 0;
  const Lines& lines = along_x ? rows_ : columns_;
  const int line = along_x ? from.y : from.x;
  const int at = along_x ? from.x : from.y;
  const int step = dx + dy;
  const int end = step > 0 ? lines.ends_forward.NextSetAfter(line, at)
                           : lines.ends_backward.PreviousSetBefore(line, at);
  const bool event = end >= 0 && end < lines.open.columns() && lines.open.Get(line, end);
  const int distance = step > 0 ? end - at : at - end;
  const int reach = event ? distance : distance - 1;  // open steps that reach cells
  const int to_goal = along_x ? (goal.x - from.x) * dx : (goal.y - from.y) * dy;
  const bool goal_on_line = along_x ? goal.y == from.y : goal.x == from.x;
  if (goal_on_line && to_goal > 0 && to_goal <= reach) {
    *found = goal;
    return true;
  }
  if (!event) return false;
  *found = {from.x + dx * distance, from.y + dy * distance};
  return true;
}

size_t StraightJumpTable::bytes() const {
  size_t total = 0;
  for (const Lines* lines : {&rows_, &columns_}) {
    for (const BitRows* bits : {&lines->open, &lines->ends_forward, &lines->ends_backward}) {
      total += static_cast<size_t>(bits->rows()) * bits->words_per_row() * sizeof(uint64_t);
    }
  }
  return total;
}

}  // namespace semnav::planning
