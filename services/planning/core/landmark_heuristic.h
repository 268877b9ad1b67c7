#pragma once

#include <algorithm>
#include <vector>

#include "services/planning/core/layered_grid.h"

namespace semnav::planning {

// Differential (landmark) heuristic for the multi-modal cost: exact costs
// d_L from a few landmark cells give h(n) = max_L |d_L(goal) - d_L(n)|, a
// consistent lower bound by the triangle inequality (every move costs the
// same both ways). Tight where octile x rolling cost is loose: around
// obstacles the path must fly over or roll round.
class LandmarkHeuristic {
 public:
  // Starts over for `grid` under `costs`; the landmarks are the passable
  // cells nearest the grid corners, none computed yet.
  void Reset(const LayeredGrid& grid, const StepCosts& costs);
  // Computes the next landmark's costs (one whole-grid Dijkstra, so callers
  // can spread them over queries); false when all are done.
  bool AddLandmark(const LayeredGrid& grid);
  void Clear();
  // Whether the last Reset() was for these costs.
  bool Matches(const StepCosts& costs) const { return valid_ && costs_ == costs; }

  // Selects the goal for Bound(), which uses the landmarks computed so far.
  void SetGoal(int goal_cell);
  // Lower bound on the cost from `cell` to the goal (infinite when they are
  // not connected). Shrunk slightly so rounding in the summed costs never
  // lifts it above the true cost.
  double Bound(int cell) const {
    double best = 0.0;
    const double* d = dist_.data() + static_cast<size_t>(cell) * landmarks_;
    for (int l = 0; l < computed_; ++l) {
      const double diff = goal_dist_[l] - d[l];
      best = std::max(best, diff < 0 ? -diff : diff);
    }
    return best * (1.0 - 1e-9);
  }

 private:
  bool valid_ = false;
  StepCosts costs_;
  std::vector<Cell> cells_;
  int landmarks_ = 0;  // cells_.size(), the per-cell stride of dist_
  int computed_ = 0;
  std::vector<double> dist_;       // cell-major, landmarks_ per cell
  std::vector<double> goal_dist_;  // the goal's row
};

}  // namespace semnav::planning
