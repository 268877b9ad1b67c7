#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "services/planning/core/layered_grid.h"

namespace semnav::planning {

// Differential (landmark) heuristic for the multi-modal cost: exact costs
// d_L from a few landmark cells give h(n) = max_L |d_L(goal) - d_L(n)|, a
// consistent lower bound by the triangle inequality (every move costs the
// same both ways). Tight where octile x rolling cost is loose: around
// obstacles the path must fly over or roll round. Immutable once built, so
// concurrent queries on one map share it.
class LandmarkHeuristic {
 public:
  static constexpr int kMaxLandmarks = 4;

  // The landmarks are the passable cells nearest the grid corners; one
  // whole-grid Dijkstra each under `costs`.
  LandmarkHeuristic(const LayeredGrid& grid, const StepCosts& costs);

  const StepCosts& costs() const { return costs_; }
  size_t bytes() const { return dist_.size() * sizeof(double); }

  // The bound towards one goal cell.
  class ToGoal {
   public:
    // Lower bound on the cost from `cell` to the goal (infinite when they
    // are not connected). Shrunk slightly so rounding in the summed costs
    // never lifts it above the true cost.
    double operator()(int cell) const {
      double best = 0.0;
      const double* d = dist_ + static_cast<size_t>(cell) * count_;
      for (int l = 0; l < count_; ++l) {
        const double diff = goal_[l] - d[l];
        best = std::max(best, diff < 0 ? -diff : diff);
      }
      return best * (1.0 - 1e-9);
    }

   private:
    friend class LandmarkHeuristic;
    const double* dist_ = nullptr;
    int count_ = 0;
    std::array<double, kMaxLandmarks> goal_{};
  };
  ToGoal Towards(int goal_cell) const;

 private:
  StepCosts costs_;
  int count_ = 0;             // landmarks, the per-cell stride of dist_
  std::vector<double> dist_;  // cell-major, count_ per cell
};

}  // namespace semnav::planning
