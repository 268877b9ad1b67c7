#include "services/planning/core/jps.h"

#include "services/planning/core/grid_search_common.h"
#include "services/planning/core/jump_scan.h"
#include "services/planning/core/octile.h"

namespace semnav::planning {
namespace {

// Plain passability: no extra stop cells.
struct PassabilitySpace {
  const PassabilityGrid& grid;
  bool Free(int x, int y) const { return IsFree(grid, x, y); }
  bool Stop(Cell) const { return false; }
  bool JumpStraight(Cell from, int dx, int dy, Cell goal, Cell* found) const {
    return ScanStraight(*this, from, dx, dy, goal, found);
  }
};

int Sign(int v) { return (v > 0) - (v < 0); }

}  // namespace

absl::StatusOr<GridPath> JpsPlanner::Plan(const PassabilityGrid& grid, Cell start, Cell goal,
                                          const SearchLimits& limits) {
  if (absl::Status s = CheckEndpoints(grid, start, goal); !s.ok()) return s;
  workspace_.Reset(grid.size());
  const int goal_index = grid.Index(goal);
  const PassabilitySpace space{grid};
  const absl::Status status = RunBestFirst(
      workspace_, grid.Index(start), OctileDistance(start, goal), goal_index, limits,
      [&](int current) {
        const Cell c = grid.CellAt(current);
        const int parent = workspace_.parent(current);
        if (parent < 0) {
          for (int m = 0; m < 8; ++m) TryDirection(grid, c, kMoveDx[m], kMoveDy[m], goal);
          return;
        }
        const Cell p = grid.CellAt(parent);
        ForEachPrunedDirection(space, c, Sign(c.x - p.x), Sign(c.y - p.y),
                               [&](int dx, int dy) { TryDirection(grid, c, dx, dy, goal); });
      });
  if (!status.ok()) return status;
  return TracePath(workspace_, grid.width(), goal_index);
}

void JpsPlanner::TryDirection(const PassabilityGrid& grid, Cell from, int dx, int dy, Cell goal) {
  const std::optional<Cell> jump = Jump(PassabilitySpace{grid}, from, dx, dy, goal);
  if (!jump) return;
  const int next = grid.Index(*jump);
  if (workspace_.Closed(next)) return;
  const double g = workspace_.g(grid.Index(from)) + OctileDistance(from, *jump);
  workspace_.Relax(next, g, g + OctileDistance(*jump, goal), grid.Index(from));
}

}  // namespace semnav::planning
