#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// EROI_UTILITY (seed 000 sec. 2.1.1, eq. 4, eq. 24, Algorithm 3) on the 2D
// explored / obstacle layers. Lengths are in cells unless noted.
struct EroiConfig {
  int eroi_size_cells = 40;     // Delta: EROI edge (2 m at 5 cm)
  int viewpoints_per_eroi = 8;  // samples on a circle round each EROI centre
  double viewpoint_radius_cells = 10.0;
  int rays = 72;                       // rays cast per viewpoint for the geometric gain
  double ray_range_cells = 100.0;      // sensor range (5 m at 5 cm)
  double connect_radius_cells = 60.0;  // roadmap edges up to this length
  double lambda = 0.01;                // eq. 24 path-cost coefficient, per cell (0.2 per m at 5 cm)
  double k = 0.8;                      // eq. 24 dynamic threshold tau = k max s
  int min_gain_cells = 0;              // viewpoints revealing fewer unknown cells are dropped
  // Clue viewpoints farther than the nearest clue viewpoint pay the path cost beyond it (false:
  // the seed's eq. 24, where every clue ignores its path length).
  bool clues_pay_extra_path = true;
};

// A map cell's state for the EROI search.
struct ExplorationLayers {
  CellGrid<uint8_t> explored;  // 1 observed
  PassabilityGrid free;        // 1 observed free
};

struct EroiChoice {
  Cell viewpoint;           // the chosen roadmap node x*
  int eroi = 0;             // index of its EROI (row-major over the EROI grid)
  double gain = 0.0;        // I: unknown cells hit by its rays
  double semantic = 0.0;    // s(x*)
  double path_cells = 0.0;  // L: roadmap path length from the robot
  double utility = 0.0;     // U by eq. 24
  std::vector<Cell> route;  // roadmap nodes from the robot to x*
};

// Number of EROIs for a grid: ceil(w / Delta) x ceil(h / Delta).
int EroiCount(int width, int height, const EroiConfig& config);

// Geometric gain of a viewpoint: distinct unexplored cells crossed by
// `rays` rays up to the range, each ray stopping at an explored obstacle.
int ViewpointGain(const ExplorationLayers& layers, Cell viewpoint, const EroiConfig& config);

// Algorithm 3. Viewpoints are sampled round the centres of active EROIs
// (some cell explored, some not) on free explored cells with gain > 0 and at
// least min_gain_cells; the
// sparse roadmap joins the robot and viewpoints closer than the connect
// radius by collision-free straight segments; Dijkstra from the robot
// expands nodes in path order; each gets U_b = I s, and U = U_b e^(-lambda
// L) unless s > tau = k max s and s is above the lowest value (a clue: eq. 23
// keeps every EROI at or above the prior), when U = U_b e^(-lambda (L - L_clue)) with L_clue the
// path to the nearest clue viewpoint (U = U_b with clues_pay_extra_path off); the best U wins.
// `semantic` holds s per EROI (size EroiCount); empty = uniform 1/N (the seed's initial value).
// nullopt when no viewpoint is reachable. `excluded` (optional) drops viewpoints: the caller's
// spent goals (a viewpoint the robot stands on keeps its gain when the camera cannot see what is
// left, and was chosen again and again at path length 0).
std::optional<EroiChoice> SelectEroiGoal(const ExplorationLayers& layers, Cell robot,
                                         const std::vector<double>& semantic,
                                         const EroiConfig& config,
                                         const std::function<bool(Cell)>& excluded = nullptr);

}  // namespace semnav::planning
