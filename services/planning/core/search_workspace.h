#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace semnav::planning {

// Per-cell search state and a binary-heap open list, reused across queries
// so a query allocates nothing once the workspace has grown to the map size.
// A generation counter marks which cells the current query has touched, so
// resetting is O(1) instead of clearing every array.
class SearchWorkspace {
 public:
  // Prepares for a new query over `cell_count` cells.
  void Reset(int cell_count) {
    if (static_cast<int>(stamp_.size()) < cell_count) {
      stamp_.assign(cell_count, 0);
      closed_.assign(cell_count, 0);
      g_.resize(cell_count);
      parent_.resize(cell_count);
      generation_ = 0;
    }
    ++generation_;
    heap_.clear();
    expansions_ = 0;
  }

  bool Reached(int cell) const { return stamp_[cell] == generation_; }
  bool Closed(int cell) const { return closed_[cell] == generation_; }
  double g(int cell) const { return g_[cell]; }
  int parent(int cell) const { return parent_[cell]; }

  // Records `g` via `parent` and queues the cell with priority `f` when it
  // improves on what the cell had; returns whether it did.
  bool Relax(int cell, double g, double f, int parent) {
    if (Reached(cell) && g >= g_[cell]) return false;
    stamp_[cell] = generation_;
    g_[cell] = g;
    parent_[cell] = parent;
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
      if (Closed(top.cell) || top.g > g_[top.cell]) continue;
      closed_[top.cell] = generation_;
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

  std::vector<uint32_t> stamp_;
  std::vector<uint32_t> closed_;
  std::vector<double> g_;
  std::vector<int> parent_;
  std::vector<Entry> heap_;
  uint32_t generation_ = 0;
  int expansions_ = 0;
};

}  // namespace semnav::planning
