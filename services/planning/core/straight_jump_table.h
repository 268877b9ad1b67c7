#pragma once

#include "services/planning/core/bit_rows.h"
#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// Straight jumps (the JPS+ idea) for one grid, kept as bits: for each
// cardinal direction, one bit per cell marks where a jump along it ends
// (an event: a stop cell, or a forced neighbour -- side cell open while the
// cell behind that side cell, towards where the move came from, is closed;
// or a closed cell). A jump is then a search for the next set bit, 64 cells
// per word (the block-based scanning of Harabor & Grastien 2014). The y
// directions use the transposed grid, so they scan words too. Building
// costs a few word operations per 64 cells, 1/16 of the memory of a table
// of run lengths.
class StraightJumpTable {
 public:
  // open/stop: row y, column x; the grid outside counts as closed.
  void Build(const BitRows& open, const BitRows& stop);

  // Jump from `from` along (dx, dy) (one of them zero). True with the event
  // cell, or `goal` if the run reaches it first, in *found. Inline: the
  // diagonal jumps call it twice per step.
  bool Jump(Cell from, int dx, int dy, Cell goal, Cell* found) const;

  size_t bytes() const;

 private:
  // Lines of cells along one axis: `open`, and where jumps moving to higher
  // / lower positions along the line end (events and closed cells).
  struct Lines {
    BitRows open;
    BitRows ends_forward;
    BitRows ends_backward;
    void Build(BitRows line_open, const BitRows& stop);
  };
  Lines rows_;     // line y, position x
  Lines columns_;  // line x, position y
};

inline bool StraightJumpTable::Jump(Cell from, int dx, int dy, Cell goal, Cell* found) const {
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

}  // namespace semnav::planning
