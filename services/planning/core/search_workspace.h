#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace semnav::planning {

// Per-cell search state and a binary-heap open list, reused across queries
// so a query allocates nothing once the workspace has grown to the map size.
// A generation counter marks which cells the current query has touched, so
// resetting is O(1) instead of clearing every array. A cell's state is one
// record, so touching a cell costs one cache line rather than four.
class SearchWorkspace {
 public:
  // Prepares for a new query over `cell_count` cells.
  void Reset(int cell_count) {
    if (static_cast<int>(cells_.size()) < cell_count) {
      cells_.assign(cell_count, CellState{});
      generation_ = 0;
    }
    ++generation_;
    heap_.clear();
    expansions_ = 0;
  }

  bool Reached(int cell) const { return cells_[cell].reached == generation_; }
  bool Closed(int cell) const { return cells_[cell].closed == generation_; }
  double g(int cell) const { return cells_[cell].g; }
  int parent(int cell) const { return cells_[cell].parent; }

  // Records `g` via `parent` and queues the cell with priority `f` when it
  // improves on what the cell had; returns whether it did.
  bool Relax(int cell, double g, double f, int parent) {
    CellState& state = cells_[cell];
    if (state.reached == generation_ && g >= state.g) return false;
    state.reached = generation_;
    state.g = g;
    state.parent = parent;
    heap_.push_back({f, g, cell});
    std::push_heap(heap_.begin(), heap_.end(), Worse);
    return true;
  }

  // Pops the open cell with the lowest f (ties: larger g, i.e. deeper),
  // skipping stale heap entries; false when the open list is empty.
  bool PopBest(int* cell) {
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), Worse);
      const Entry top = heap_.back();
      heap_.pop_back();
      CellState& state = cells_[top.cell];
      if (state.closed == generation_ || top.g > state.g) continue;
      state.closed = generation_;
      ++expansions_;
      *cell = top.cell;
      return true;
    }
    return false;
  }

  int expansions() const { return expansions_; }

 private:
  struct Entry {
    double f;
    double g;
    int cell;
  };
  // Heap order as a functor type so std::push_heap/pop_heap inline it.
  struct WorseEntry {
    bool operator()(const Entry& a, const Entry& b) const {
      return a.f > b.f || (a.f == b.f && a.g < b.g);
    }
  };
  static constexpr WorseEntry Worse{};

  struct CellState {
    uint32_t reached = 0;  // generation that last reached / closed the cell
    uint32_t closed = 0;
    double g = 0.0;
    int parent = -1;
  };

  std::vector<CellState> cells_;
  std::vector<Entry> heap_;
  uint32_t generation_ = 0;
  int expansions_ = 0;
};

}  // namespace semnav::planning
