#pragma once

#include <optional>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

struct CoverageGoalConfig {
  // Seed 004 algorithm box: re-plan the long-term goal after L_MAX steps
  // (the seed gives no value; 25 steps of 0.25 m = about 6 m of travel).
  int l_max_steps = 25;
  // When the boundary point ahead is unreachable the heading is turned by
  // this step (alternating left/right) until one is reachable, which is the
  // seed's "turns around at a dead end" behaviour.
  double turn_step_rad = 0.5235987755982988;  // 30 degrees
};

// COVERAGE_MAX (seed 004 sec. 2.3): the long-term goal on the map boundary
// ahead of the robot,
//   p_subgoal = (x + sqrt(2) K / 2 cos(theta), y + sqrt(2) K / 2 sin(theta)),
// clamped into the K x K map (K = the larger side, cells). `free` must treat
// unexplored cells as free (the seed plans through unknown space). Returns
// the reachable boundary goal nearest the heading, or nullopt.
std::optional<Cell> CoverageMaxGoal(const PassabilityGrid& free, Cell robot, double yaw_rad,
                                    const CoverageGoalConfig& config);

// The seed's re-plan test: after more than L_MAX steps, or when the path to
// the current goal failed.
inline bool CoverageGoalExpired(int steps_since_goal, bool path_failed,
                                const CoverageGoalConfig& config) {
  return path_failed || steps_since_goal > config.l_max_steps;
}

}  // namespace semnav::planning
