#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "services/planning/core/cell_grid.h"
#include "services/planning/core/coverage_goal.h"
#include "services/planning/core/eroi_utility.h"
#include "services/planning/core/footprint_reach.h"
#include "services/planning/core/frontier.h"
#include "services/planning/core/frontier_scoring.h"
#include "services/planning/core/frontier_value.h"
#include "services/planning/core/grid_padding.h"
#include "services/planning/core/semantic_discount.h"

namespace semnav::planning {

enum class ExplorationStrategy { kNearestFrontier, kCoverageMax, kSemanticFrontier, kEroiUtility };

// The grid exploration reads, placed in the map frame.
struct ExplorationGrid {
  double resolution_m = 0.05;
  double origin_x = 0.0;
  double origin_y = 0.0;
  CellGrid<uint8_t> explored;  // 1 observed
  PassabilityGrid free;        // unknown counts as blocked
  // A ground robot's footprint: the frontier strategies reach frontiers as its planner does and
  // answer the cell it stands on (footprint_reach.h); unset = a point robot on `free`.
  std::optional<FootprintReachConfig> footprint;
  Point2 CentreOf(Cell c) const {
    return {origin_x + (c.x + 0.5) * resolution_m, origin_y + (c.y + 0.5) * resolution_m};
  }
  Point2 CentreOf(double col, double row) const {
    return {origin_x + (col + 0.5) * resolution_m, origin_y + (row + 0.5) * resolution_m};
  }
  // The cell a map-frame point lies in (off the grid for a point outside it).
  Cell CellOf(Point2 p) const {
    return {static_cast<int>(std::floor((p.x - origin_x) / resolution_m)),
            static_cast<int>(std::floor((p.y - origin_y) / resolution_m))};
  }
};

// Everything the caller knows for one choice (map frame, metres).
struct ExplorationQuery {
  Cell robot;
  double robot_yaw_rad = 0.0;
  int min_frontier_cells = 5;
  std::vector<ScoredObject> objects;
  std::vector<Point2> visited;
  // A goal must not be chosen here (near a goal the caller could not reach, or outside the
  // operator's search area); unset = nowhere.
  std::function<bool(Point2)> excluded;
  // Outside the operator's search area (EROI counts it as explored); unset = nowhere.
  std::function<bool(Point2)> outside_area;
  std::vector<double> eroi_values;  // EROI_UTILITY semantic values; empty = uniform
  // SEMANTIC_FRONTIER's rule: the discount on the platforms its config names, else the seed total.
  ExplorationPlatform platform = ExplorationPlatform::kUnspecified;
  // The caller's current goal: the frontier strategies answer the reachable frontier cell
  // nearest it while one lies within keep_radius_m (the frontier is not cleared yet); unset =
  // the strategy's best.
  std::optional<Point2> keep_goal;
  double keep_radius_m = 1.0;
};

struct ExplorationGoalConfig {
  FrontierScoreConfig score;  // seed 002 terms (reported; SEMANTIC_FRONTIER with value map off)
  FrontierValueConfig value;  // SEMANTIC_FRONTIER's value map (opt-in, before the discount)
  SemanticDiscountConfig discount;  // SEMANTIC_FRONTIER's discounted nearest frontier (by platform)
  CoverageGoalConfig coverage;
  EroiConfig eroi;  // cells
};

// Frontiers with the excluded cells removed, their path distances and scores.
struct FrontierSet {
  std::vector<Frontier> frontiers;
  std::vector<FrontierCandidate> candidates;  // metres, path distances (-1 unreachable)
  std::vector<Cell> nearest_cells;            // each frontier's cell nearest by path
  // Octile path distance from the robot to every cell (cells); with a footprint, to where the
  // robot stands to reach each frontier cell.
  std::vector<double> path_cells;
  std::vector<FrontierScore> scores;    // seed 002
  std::optional<FootprintReach> reach;  // set with the grid's footprint
};

FrontierSet CollectFrontiers(const ExplorationGrid& grid, const ExplorationQuery& query,
                             const FrontierScoreConfig& score);

// A robot that stands up to `max_outside_m` beyond the grid's edge (at the start the camera has
// not seen the cell it stands on, so the map it drew may end in front of it) is taken in as
// GridPlanner takes in such a start: the grid grows to the robot's cell, the strip between
// passable (the robot stands in it) and unexplored. Returns the padding, none when the robot is
// inside; INVALID_ARGUMENT naming "robot" when it lies farther out.
absl::StatusOr<Padding> TakeInRobot(ExplorationGrid& grid, ExplorationQuery& query,
                                    double max_outside_m);

struct ExplorationChoice {
  Cell goal;
  double score = 0.0;       // strategy-specific (distance m, seed 002 total, utility)
  std::vector<Cell> route;  // EROI_UTILITY's route; empty otherwise
};

// The exploration goal by strategy. NEAREST_FRONTIER and COVERAGE_MAX are the seed 004
// baselines; SEMANTIC_FRONTIER takes the value map (frontier_value.h) when it is on, else, on the
// platforms the discount applies to, the semantically discounted nearest frontier
// (semantic_discount.h; goal: its nearest cell, as NEAREST_FRONTIER's), else the best seed 002
// total; EROI_UTILITY is seed 000's utility. NOT_FOUND with reason NO_EXPLORATION_GOAL when
// nothing is reachable. NEAREST_FRONTIER and SEMANTIC_FRONTIER keep query.keep_goal's frontier
// while it is open. INVALID_ARGUMENT naming eroi_semantic_values when their count does not
// match the grid. With the grid's footprint, the frontier strategies answer the cell the robot
// stands on to reach their frontier cell.
absl::StatusOr<ExplorationChoice> SelectExplorationGoal(const ExplorationGrid& grid,
                                                        const ExplorationQuery& query,
                                                        ExplorationStrategy strategy,
                                                        const ExplorationGoalConfig& config);

}  // namespace semnav::planning
