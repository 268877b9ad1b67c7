#pragma once

#include <optional>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// How a disc robot reaches cells (cells of the grid the planners read).
struct FootprintReachConfig {
  double radius_cells = 0.0;  // footprint radius the planners inflate by
  // A cell counts as reached from a standing cell within this distance: a frontier cell's
  // inflated surroundings (the unknown beyond it, a wall or furniture beside it) push the stand
  // back by up to a radius on each side.
  double reach_cells = 0.0;
  // The robot also starts from every free cell this close, as GridPlanner leaves a start the
  // inflation blocks or boxes in (its start_snap_radius_m).
  double start_snap_cells = 0.0;
  // Stands still free at this larger inflation (the planner's first try, with the path
  // clearance) are preferred when one reaches the cell; <= radius_cells = no preference.
  double clear_radius_cells = 0.0;
};

// Where a disc robot can stand to reach each cell. The planners inflate blocked cells by the
// robot radius, so a frontier cell beside a wall is not a cell a path can end on, and one seen
// through a gap narrower than the robot is not reachable at all. A cell is
// reached from the footprint-free cell, connected to the robot, within reach_cells of it that
// is nearest by path (the path plus the straight reach).
class FootprintReach {
 public:
  // `free`: explored free cells (unknown blocked), inflated as a whole: a stand's footprint
  // stays on seen free space, which PlanPath accepts whether or not it takes unknown as free.
  FootprintReach(const PassabilityGrid& free, Cell robot, const FootprintReachConfig& config);

  // Path distance in cells from the robot to stand where `c` is reached; kUnreachable when no
  // footprint-free connected cell lies within reach.
  double Distance(Cell c) const;
  // The cell to stand on to reach `c`; nullopt when unreachable.
  std::optional<Cell> StandFor(Cell c) const;
  // Octile path distance from the robot on the inflated grid (kUnreachable off it).
  const std::vector<double>& field() const { return field_; }

 private:
  struct Stand {
    double distance;  // path to the stand plus the reach from it
    double reach;     // straight distance from the stand to the cell
    std::optional<Cell> cell;
  };
  Stand Best(Cell c) const;

  PassabilityGrid inflated_;
  std::optional<PassabilityGrid> clear_;  // preferred stands; none = no preference
  std::vector<double> field_;
  std::vector<Cell> reach_disc_;
};

}  // namespace semnav::planning
