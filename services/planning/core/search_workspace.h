#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace semnav::planning {

// Per-cell search state and a binary-heap open list, reused across queries
// so a query allocates nothing once the workspace has grown to the map size.
// A generation counter marks which cells the current query has touched, so
// resetting is O(1) instead of clearing every array. A cell's state is one
// 16-byte record, so touching a cell costs one cache line rather than four.
class SearchWorkspace {
 public:
  // Prepares for a new query over `cell_count` cells.
  void Reset(int cell_count) {
    if (static_cast<int>(cells_.size()) < cell_count || generation_ == kLastGeneration) {
      cells_.assign(std::max<size_t>(cells_.size(), cell_count), CellState{});
      generation_ = 0;
    }
    ++generation_;
    heap_.clear();
    expansions_ = 0;
  }

  bool Reached(int cell) const { return cells_[cell].mark >= 2 * generation_; }
  bool Closed(int cell) const { return cells_[cell].mark == 2 * generation_ + 1; }
  double g(int cell) const { return cells_[cell].g; }
  int parent(int cell) const { return cells_[cell].parent; }

  // Records `g` via `parent` and queues the cell with priority `f` when it
  // improves on what the cell had; returns whether it did.
  bool Relax(int cell, double g, double f, int parent) {
    CellState& state = cells_[cell];
    if (state.mark >= 2 * generation_ && g >= state.g) return false;
    state.mark = 2 * generation_;
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
      if (state.mark == 2 * generation_ + 1 || top.g > state.g) continue;
      state.mark = 2 * generation_ + 1;
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
    // 2 x generation: reached (open) in that query; + 1: closed. Older
    // values mean untouched by the current query.
    uint32_t mark = 0;
    int parent = -1;
    double g = 0.0;
  };
  static constexpr uint32_t kLastGeneration = (UINT32_MAX - 1) / 2;

  std::vector<CellState> cells_;
  std::vector<Entry> heap_;
  uint32_t generation_ = 0;
  int expansions_ = 0;
};

}  // namespace semnav::planning
