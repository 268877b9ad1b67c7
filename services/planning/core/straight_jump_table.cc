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
