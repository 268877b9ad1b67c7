#include "services/planning/core/exploration_goal.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/planning/core/distance_field.h"

namespace semnav::planning {
namespace {

// Drops the frontier cells the caller excluded (near excluded goals: the part the robot could
// not clear; outside the search area), then clusters left smaller than min_cells; centroid and
// anchor are those of the cells kept.
std::vector<Frontier> WithoutExcludedCells(std::vector<Frontier> frontiers,
                                           const ExplorationGrid& grid,
                                           const std::function<bool(Point2)>& excluded,
                                           int min_cells) {
  std::vector<Frontier> kept;
  for (Frontier& f : frontiers) {
    std::erase_if(f.cells, [&](const Cell& c) { return excluded(grid.CentreOf(c)); });
    if (f.cells.empty() || static_cast<int>(f.cells.size()) < min_cells) continue;
    double sx = 0.0, sy = 0.0;
    for (const Cell& c : f.cells) {
      sx += c.x;
      sy += c.y;
    }
    f.centroid_x = sx / f.cells.size();
    f.centroid_y = sy / f.cells.size();
    f.anchor = *std::min_element(f.cells.begin(), f.cells.end(), [&](const Cell& a, const Cell& b) {
      return std::hypot(a.x - f.centroid_x, a.y - f.centroid_y) <
             std::hypot(b.x - f.centroid_x, b.y - f.centroid_y);
    });
    kept.push_back(std::move(f));
  }
  return kept;
}

// The reachable frontier cell nearest the caller's current goal, when one lies within
// keep_radius_m of it, and that frontier's index: the goal's frontier is still open.
std::optional<std::pair<Cell, int>> KeptFrontierCell(const FrontierSet& set,
                                                     const ExplorationGrid& grid,
                                                     const ExplorationQuery& query) {
  if (!query.keep_goal.has_value()) return std::nullopt;
  std::optional<std::pair<Cell, int>> kept;
  double nearest = query.keep_radius_m;
  for (size_t i = 0; i < set.frontiers.size(); ++i) {
    if (set.candidates[i].path_distance_m < 0) continue;
    for (const Cell& c : set.frontiers[i].cells) {
      const Point2 p = grid.CentreOf(c);
      const double d = std::hypot(p.x - query.keep_goal->x, p.y - query.keep_goal->y);
      if (d <= nearest) {
        nearest = d;
        kept = std::pair{c, static_cast<int>(i)};
      }
    }
  }
  return kept;
}

// A frontier strategy's goal cell as the cell the robot stands on to reach it (a footprint is
// given), else that of its frontier's cell nearest by path; the cell itself for a point robot.
ExplorationChoice Standing(const FrontierSet& set, ExplorationChoice choice, int frontier) {
  if (!set.reach.has_value()) return choice;
  std::optional<Cell> stand = set.reach->StandFor(choice.goal);
  if (!stand) stand = set.reach->StandFor(set.nearest_cells[frontier]);
  if (stand) choice.goal = *stand;
  return choice;
}

absl::Status NotFound(absl::string_view message) {
  return FieldStatus(absl::StatusCode::kNotFound, "", message, "NO_EXPLORATION_GOAL");
}

}  // namespace

FrontierSet CollectFrontiers(const ExplorationGrid& grid, const ExplorationQuery& query,
                             const FrontierScoreConfig& score) {
  FrontierSet set;
  set.frontiers = ExtractFrontiers(grid.explored, grid.free, query.min_frontier_cells);
  if (query.excluded) {
    set.frontiers = WithoutExcludedCells(std::move(set.frontiers), grid, query.excluded,
                                         query.min_frontier_cells);
  }
  if (grid.footprint.has_value()) {
    set.reach.emplace(grid.free, query.robot, *grid.footprint);
    set.path_cells = set.reach->field();
    for (const Frontier& f : set.frontiers) {
      for (const Cell& c : f.cells) set.path_cells[grid.free.Index(c)] = set.reach->Distance(c);
    }
  } else {
    set.path_cells = OctileDistanceField(grid.free, query.robot);
  }
  const std::vector<double>& distance = set.path_cells;
  for (const Frontier& f : set.frontiers) {
    double nearest = kUnreachable;
    Cell nearest_cell = f.anchor;
    for (const Cell& c : f.cells) {
      if (distance[grid.free.Index(c)] < nearest) {
        nearest = distance[grid.free.Index(c)];
        nearest_cell = c;
      }
    }
    set.candidates.push_back({grid.CentreOf(f.centroid_x, f.centroid_y),
                              nearest == kUnreachable ? -1.0 : nearest * grid.resolution_m});
    set.nearest_cells.push_back(nearest_cell);
  }
  set.scores = ScoreFrontiers(set.candidates, grid.CentreOf(query.robot), query.visited,
                              query.objects, score);
  return set;
}

absl::StatusOr<Padding> TakeInRobot(ExplorationGrid& grid, ExplorationQuery& query,
                                    double max_outside_m) {
  const Padding pad = PaddingFor(grid.free.width(), grid.free.height(), query.robot);
  if (!pad.any()) return pad;
  const double outside_m = pad.OutsideCells() * grid.resolution_m;
  if (!(outside_m <= max_outside_m)) {
    return InvalidField(
        "robot", absl::StrCat("robot is ", outside_m, " m outside the ", grid.free.width(), " x ",
                              grid.free.height(), " grid (max ", max_outside_m, " m)"));
  }
  if (PaddedCells(grid.free.width(), grid.free.height(), pad) > kMaxPaddedCells) {
    return InvalidField("robot", absl::StrCat("the grid padded to the robot would exceed ",
                                              kMaxPaddedCells, " cells"));
  }
  grid.explored = Padded<uint8_t>(grid.explored, pad, 0);
  grid.free = Padded<uint8_t>(grid.free, pad, 1);
  grid.origin_x -= pad.left * grid.resolution_m;
  grid.origin_y -= pad.bottom * grid.resolution_m;
  query.robot = IntoPadded(query.robot, pad);
  return pad;
}

absl::StatusOr<ExplorationChoice> SelectExplorationGoal(const ExplorationGrid& grid,
                                                        const ExplorationQuery& query,
                                                        ExplorationStrategy strategy,
                                                        const ExplorationGoalConfig& config) {
  switch (strategy) {
    case ExplorationStrategy::kCoverageMax: {
      // Seed 004: unknown space counts as free for the long-term goal.
      PassabilityGrid open = grid.free;
      for (int i = 0; i < open.size(); ++i) {
        if (grid.explored.values()[i] == 0) open.values()[i] = 1;
      }
      // Excluded goals' surroundings and cells outside the search area cannot hold the goal.
      if (query.excluded) {
        for (int y = 0; y < open.height(); ++y) {
          for (int x = 0; x < open.width(); ++x) {
            if (query.excluded(grid.CentreOf(Cell{x, y}))) open.at(x, y) = 0;
          }
        }
      }
      const std::optional<Cell> goal =
          CoverageMaxGoal(open, query.robot, query.robot_yaw_rad, config.coverage);
      if (!goal) return NotFound("no reachable boundary goal in any direction");
      return ExplorationChoice{*goal, 0.0, {}};
    }
    case ExplorationStrategy::kSemanticFrontier: {
      const FrontierSet set = CollectFrontiers(grid, query, config.score);
      if (const auto kept = KeptFrontierCell(set, grid, query)) {
        return Standing(set, {kept->first, set.scores[kept->second].total, {}}, kept->second);
      }
      std::optional<int> best;
      double score = 0.0;
      if (config.value.enabled) {
        const std::vector<FrontierValue> values =
            ValueFrontiers(set.frontiers, set.candidates, grid.explored, grid.resolution_m,
                           query.objects, config.value);
        best = SelectValuedFrontier(set.candidates, values, config.value);
        if (best) score = values[*best].utility;
      } else if (DiscountApplies(config.discount, query.platform)) {
        best = SelectDiscountedFrontier(set.candidates, set.scores, config.discount);
        if (!best) return NotFound("no reachable frontier");
        return Standing(set, {set.nearest_cells[*best], set.scores[*best].total, {}}, *best);
      } else {
        for (size_t i = 0; i < set.scores.size(); ++i) {
          if (set.candidates[i].path_distance_m < 0) continue;
          if (!best || set.scores[i].total > set.scores[*best].total) best = static_cast<int>(i);
        }
        if (best) score = set.scores[*best].total;
      }
      if (!best) return NotFound("no reachable frontier");
      return Standing(set, {set.frontiers[*best].anchor, score, {}}, *best);
    }
    case ExplorationStrategy::kEroiUtility: {
      const int count = EroiCount(grid.explored.width(), grid.explored.height(), config.eroi);
      if (!query.eroi_values.empty() && static_cast<int>(query.eroi_values.size()) != count) {
        return InvalidField("eroi_semantic_values",
                            absl::StrCat("eroi_semantic_values has ", query.eroi_values.size(),
                                         " values; this grid has ", count, " EROIs"));
      }
      // Outside the search area counts as explored (no information to gain there) and blocked:
      // no viewpoint there and no roadmap edge through it. A UAV's map reaches past the area's
      // edge, and a free viewpoint there used to take it out of the world.
      CellGrid<uint8_t> explored = grid.explored;
      PassabilityGrid free = grid.free;
      if (query.outside_area) {
        for (int y = 0; y < explored.height(); ++y) {
          for (int x = 0; x < explored.width(); ++x) {
            if (!query.outside_area(grid.CentreOf(Cell{x, y}))) continue;
            explored.at(x, y) = 1;
            free.at(x, y) = 0;
          }
        }
      }
      // Spent goals (and the outside of the area) hold no viewpoint, as for the frontier
      // strategies.
      std::function<bool(Cell)> excluded;
      if (query.excluded) excluded = [&](Cell c) { return query.excluded(grid.CentreOf(c)); };
      const std::optional<EroiChoice> choice =
          SelectEroiGoal({explored, free}, query.robot, query.eroi_values, config.eroi, excluded);
      if (!choice) return NotFound("no reachable EROI viewpoint");
      return ExplorationChoice{choice->viewpoint, choice->utility, choice->route};
    }
    case ExplorationStrategy::kNearestFrontier:
      break;
  }
  const FrontierSet set = CollectFrontiers(grid, query, config.score);
  if (const auto kept = KeptFrontierCell(set, grid, query)) {
    return Standing(set, {kept->first, set.candidates[kept->second].path_distance_m, {}},
                    kept->second);
  }
  const std::optional<NearestFrontier> nearest =
      SelectNearestFrontier(set.frontiers, grid.free, set.path_cells);
  if (!nearest) return NotFound("no reachable frontier");
  return Standing(set, {nearest->cell, nearest->distance_cells * grid.resolution_m, {}},
                  nearest->frontier);
}

}  // namespace semnav::planning
