#include "services/planning/core/jump_astar.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/planning/core/grid_path.h"
#include "services/planning/core/grid_search_common.h"
#include "services/planning/core/jump_scan.h"
#include "services/planning/core/octile.h"
#include "services/planning/core/plan_failure.h"

namespace semnav::planning {
namespace {

// Two f values this close count as equal when deciding whether a diagonal
// jump point can be skipped (only the amount of work depends on it).
constexpr double kSameF = 1e-9;

// One uniform region for the jump rules: structure blocks, boundary cells
// stop jumps, straight jumps come from the precomputed table.
struct RegionSpace {
  const LayeredGrid& grid;
  const RegionTables& tables;
  bool Free(int x, int y) const { return Passable(grid, x, y); }
  bool Stop(Cell c) const { return tables.Boundary(c); }
  bool JumpStraight(Cell from, int dx, int dy, Cell goal, Cell* found) const {
    return tables.jumps().Jump(from, dx, dy, goal, found);
  }
};

// The tallest obstacle value a unit move touches (both cells, and both side cells of a diagonal);
// structure is never touched by a passable move.
uint8_t TallestTouched(const LayeredGrid& grid, Cell from, int dx, int dy) {
  uint8_t top = std::max(grid.at(from), grid.at(from.x + dx, from.y + dy));
  if (dx != 0 && dy != 0) {
    top = std::max({top, grid.at(from.x + dx, from.y), grid.at(from.x, from.y + dy)});
  }
  return top;
}

// Splits the cell path into maximal single-mode segments with their
// lengths and eq. 10 / eq. 12 energies, and reduces the waypoints to the
// turning points (heading or mode changes).
void Summarise(const LayeredGrid& grid, const JumpAStarOptions& options, MultiModalPath* path) {
  const std::vector<Cell> cells = ExpandWaypoints(path->waypoints);
  path->waypoints.assign(1, cells.front());
  int last_dx = 0;
  int last_dy = 0;
  for (size_t i = 1; i < cells.size(); ++i) {
    const int dx = cells[i].x - cells[i - 1].x;
    const int dy = cells[i].y - cells[i - 1].y;
    MotionMode mode = MotionMode::kRolling;
    ClassifyMove(grid, cells[i - 1], dx, dy, &mode);
    const double length = (dx != 0 && dy != 0 ? kSqrt2 : 1.0) * options.resolution_m;
    const bool flying = mode == MotionMode::kFlying;
    const double energy =
        length * (flying ? options.energy.FlyingJPerM() : options.energy.rolling_j_per_m);
    const bool new_segment = path->segments.empty() || path->segments.back().mode != mode;
    if (i > 1 && (new_segment || dx != last_dx || dy != last_dy)) {
      path->waypoints.push_back(cells[i - 1]);
    }
    if (new_segment) {
      const int at = static_cast<int>(path->waypoints.size()) - 1;
      path->segments.push_back({cells[i - 1], cells[i - 1], at, at, mode, 0.0, 0.0, 0});
    }
    ModalSegment& segment = path->segments.back();
    if (flying) segment.top = std::max(segment.top, TallestTouched(grid, cells[i - 1], dx, dy));
    segment.to = cells[i];
    segment.last_point = static_cast<int>(path->waypoints.size());  // cells[i] comes next
    segment.length_m += length;
    segment.energy_j += energy;
    (flying ? path->fly_m : path->roll_m) += length;
    path->energy_j += energy;
    last_dx = dx;
    last_dy = dy;
  }
  if (cells.size() > 1) path->waypoints.push_back(cells.back());
  path->length_m = path->fly_m + path->roll_m;
  path->switches = path->segments.empty() ? 0 : static_cast<int>(path->segments.size()) - 1;
}

}  // namespace

absl::Status CheckMultiModalEndpoints(const LayeredGrid& grid, Cell start, Cell goal) {
  for (auto [cell, field] : {std::pair{start, "start"}, std::pair{goal, "goal"}}) {
    if (!grid.Contains(cell)) {
      return InvalidField(field,
                          absl::StrCat(field, " (", cell.x, ", ", cell.y, ") is outside the grid"));
    }
  }
  if (grid.at(start) >= kStructureValue) {
    return MakePlanFailure(PlanFailure::kStartOccupied, "start is on building structure");
  }
  if (grid.at(goal) >= kStructureValue) {
    return MakePlanFailure(PlanFailure::kGoalOccupied, "goal is on building structure");
  }
  return absl::OkStatus();
}

double FlightAltitude(uint8_t top, double foot_m, double ceiling_m, double margin_m) {
  if (top == 0 || !(ceiling_m > foot_m)) return 0.0;
  return foot_m + (top + 0.5) / 100.0 * (ceiling_m - foot_m) + margin_m;
}

void PrependStart(Cell start, const JumpAStarOptions& options, MultiModalPath* path) {
  if (path->waypoints.empty()) return;
  const Cell first = path->waypoints.front();
  const double length = std::hypot(first.x - start.x, first.y - start.y) * options.resolution_m;
  path->waypoints.insert(path->waypoints.begin(), start);
  if (path->segments.empty()) {
    path->segments.push_back({start, first, 0, 1, MotionMode::kRolling, 0.0, 0.0, 0});
  } else {
    for (ModalSegment& s : path->segments) {
      ++s.first_point;
      ++s.last_point;
    }
  }
  ModalSegment& head = path->segments.front();
  head.from = start;
  head.first_point = 0;
  const bool flying = head.mode == MotionMode::kFlying;
  const double energy = flying ? options.energy.Fly(length) : options.energy.Roll(length);
  head.length_m += length;
  head.energy_j += energy;
  (flying ? path->fly_m : path->roll_m) += length;
  path->length_m += length;
  path->energy_j += energy;
}

StepCosts StepCostsOf(const JumpAStarOptions& options) {
  const double unit = options.resolution_m / options.energy_unit_j;
  return {
      options.alpha * options.resolution_m + options.beta * options.energy.rolling_j_per_m * unit,
      options.alpha * options.resolution_m + options.beta * options.energy.FlyingJPerM() * unit};
}

absl::StatusOr<MultiModalPath> JumpAStarPlanner::Plan(const LayeredGrid& grid, Cell start,
                                                      Cell goal, const JumpAStarOptions& options,
                                                      const SearchLimits& limits) {
  if (absl::Status s = CheckMultiModalEndpoints(grid, start, goal); !s.ok()) return s;
  if (!options.jump_pruning) return Search(grid, nullptr, nullptr, start, goal, options, limits);
  const RegionTables map(grid);
  return Search(map.grid(), &map, nullptr, start, goal, options, limits);
}

absl::StatusOr<MultiModalPath> JumpAStarPlanner::Plan(const RegionTables& map,
                                                      const LandmarkHeuristic* landmarks,
                                                      Cell start, Cell goal,
                                                      const JumpAStarOptions& options,
                                                      const SearchLimits& limits) {
  const LayeredGrid& grid = map.grid();
  if (absl::Status s = CheckMultiModalEndpoints(grid, start, goal); !s.ok()) return s;
  return Search(grid, options.jump_pruning ? &map : nullptr, landmarks, start, goal, options,
                limits);
}

absl::StatusOr<MultiModalPath> JumpAStarPlanner::Search(
    const LayeredGrid& grid, const RegionTables* regions, const LandmarkHeuristic* landmarks,
    Cell start, Cell goal, const JumpAStarOptions& options, const SearchLimits& limits) {
  const StepCosts costs = StepCostsOf(options);
  const bool prune = regions != nullptr;
  const int goal_index = grid.Index(goal);
  const bool use_landmarks = landmarks != nullptr && landmarks->costs() == costs;
  const LandmarkHeuristic::ToGoal bound =
      use_landmarks ? landmarks->Towards(goal_index) : LandmarkHeuristic::ToGoal();
  auto heuristic = [&](Cell c) {
    const double octile = costs.roll * OctileDistance(c, goal);
    return use_landmarks ? std::max(octile, bound(grid.Index(c))) : octile;
  };
  // Without pruning every cell expands fully (the plain A* reference).
  auto jumps_through = [&](Cell cell) { return prune && !regions->Boundary(cell); };

  workspace_.Reset(grid.size());
  auto relax = [&](int from, Cell to, double step_cost) {
    const int next = grid.Index(to);
    if (workspace_.Closed(next)) return;
    const double g = workspace_.g(from) + step_cost;
    workspace_.Relax(next, g, g + heuristic(to), from);
  };
  // Cells whose own expansion ignores the direction they were reached from.
  auto expands_fully = [&](Cell cell) { return cell == goal || regions->Boundary(cell); };
  // Jumps from the expanded cell `c` (index `from`). A jump stays in the
  // region of `c`, so every step has the region's cost.
  auto try_jump = [&](int from, Cell c, int dx, int dy) {
    const RegionSpace space{grid, *regions};
    const double step = IsObstacle(grid.at(c)) ? costs.fly : costs.roll;
    auto relax_jump = [&](Cell to) { relax(from, to, step * OctileDistance(c, to)); };
    Cell found;
    if (dx == 0 || dy == 0) {
      if (space.JumpStraight(c, dx, dy, goal, &found)) relax_jump(found);
      return;
    }
    // The diagonal jump of jump_scan.h, with one shortcut: a diagonal jump
    // point `at` whose straight jumps only reach fully expanded cells, and
    // whose f equals f(c) (it would be popped next anyway), is not queued;
    // its straight successors are relaxed from `c` directly (their path
    // c -> at -> successor is the diagonal-first run ExpandWaypoints
    // draws) and the diagonal goes on. Expanding `at` would relax the same
    // cells at the same cost, so the optimum is unchanged.
    const double f_from = workspace_.g(from) + heuristic(c);
    Cell at = c;
    while (CanStepDiagonal(space, at, dx, dy)) {
      at.x += dx;
      at.y += dy;
      if (at == goal || space.Stop(at)) return relax_jump(at);
      Cell along_x;
      Cell along_y;
      const bool hit_x = space.JumpStraight(at, dx, 0, goal, &along_x);
      const bool hit_y = space.JumpStraight(at, 0, dy, goal, &along_y);
      if (!hit_x && !hit_y) continue;
      const bool bypass =
          (!hit_x || expands_fully(along_x)) && (!hit_y || expands_fully(along_y)) &&
          workspace_.g(from) + step * OctileDistance(c, at) + heuristic(at) <= f_from + kSameF;
      if (!bypass) return relax_jump(at);
      if (hit_x) relax_jump(along_x);
      if (hit_y) relax_jump(along_y);
    }
  };
  auto expand = [&](int current) {
    const Cell c = grid.CellAt(current);
    const int parent = workspace_.parent(current);
    if (parent >= 0 && jumps_through(c)) {
      const Cell p = grid.CellAt(parent);
      ForEachPrunedDirection(RegionSpace{grid, *regions}, c, (c.x > p.x) - (c.x < p.x),
                             (c.y > p.y) - (c.y < p.y),
                             [&](int dx, int dy) { try_jump(current, c, dx, dy); });
      return;
    }
    const bool in_obstacle = IsObstacle(grid.at(c));
    ForEachMove(grid, c, [&](Cell n, MotionMode mode, double cells) {
      const bool same_region =
          IsObstacle(grid.at(n)) == in_obstacle && (mode == MotionMode::kFlying) == in_obstacle;
      if (same_region && jumps_through(n)) {
        try_jump(current, c, n.x - c.x, n.y - c.y);
      } else {
        relax(current, n, costs.Of(mode) * cells);
      }
    });
  };
  const absl::Status status =
      RunBestFirst(workspace_, grid.Index(start), heuristic(start), goal_index, limits, expand);
  if (!status.ok()) return status;
  const GridPath trace = TracePath(workspace_, grid.width(), goal_index);
  MultiModalPath path;
  path.waypoints = trace.waypoints;
  path.cost = trace.length_cells;
  path.expansions = trace.expansions;
  Summarise(grid, options, &path);
  return path;
}

}  // namespace semnav::planning
