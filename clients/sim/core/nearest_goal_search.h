// Which point of a success region a shortest path should end at: the region is a set of cells
// (within the success radius of any target instance), and SPL's l_i runs to the nearest one.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

#include "clients/sim/core/occupancy_raster.h"

namespace semnav::sim {

struct NearestGoal {
  Eigen::Vector2d goal;               // centre of the nearest goal cell, world xy
  double length_m = 0.0;              // its path length from the start cell's centre
  std::vector<Eigen::Vector2d> path;  // cell centres from the start's cell to the goal's
};

// Dijkstra from the cell holding `start` over the free (0) cells of `grid`, 8-connected with
// octile steps and no corner cutting (a diagonal needs both side cells free), stopping at the
// first cell whose centre satisfies `is_goal`. nullopt when the start is outside the grid or
// occupied, or no goal cell is reachable.
std::optional<NearestGoal> NearestReachableGoal(
    const GroundTruthGrid& grid, const Eigen::Vector2d& start,
    const std::function<bool(const Eigen::Vector2d&)>& is_goal);

}  // namespace semnav::sim
