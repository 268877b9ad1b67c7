#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// A frontier: a connected (8-neighbour) cluster of explored free cells that
// touch unexplored space (Yamauchi's frontier, the FrontierExp baseline of
// seed 004 and the input of seed 002's scorer).
struct Frontier {
  std::vector<Cell> cells;
  double centroid_x = 0.0;  // mean cell column
  double centroid_y = 0.0;  // mean cell row
  Cell anchor;              // the cluster cell nearest the centroid (a reachable target)
};

// Frontier cells are explored (explored != 0), free (free != 0) and have an
// unexplored 4-neighbour; clusters smaller than min_cells are dropped.
std::vector<Frontier> ExtractFrontiers(const CellGrid<uint8_t>& explored,
                                       const PassabilityGrid& free, int min_cells);

// NEAREST_FRONTIER (FrontierExp, seed 004 baseline): the frontier cell with
// the shortest octile path from the robot over free cells; nullopt when no
// frontier cell is reachable. `path_cells` is OctileDistanceField(free, robot),
// which the caller has already built to score the frontiers.
struct NearestFrontier {
  int frontier = 0;  // index into the frontier list
  Cell cell;
  double distance_cells = 0.0;
};
std::optional<NearestFrontier> SelectNearestFrontier(const std::vector<Frontier>& frontiers,
                                                     const PassabilityGrid& free,
                                                     const std::vector<double>& path_cells);

}  // namespace semnav::planning
