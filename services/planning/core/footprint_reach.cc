#include "services/planning/core/footprint_reach.h"

#include <cmath>

#include "services/planning/core/distance_field.h"
#include "services/planning/core/inflation.h"

namespace semnav::planning {

FootprintReach::FootprintReach(const PassabilityGrid& free, Cell robot,
                               const FootprintReachConfig& config)
    : inflated_(InflateObstacles(free, config.radius_cells)),
      reach_disc_(DiscOffsets(config.reach_cells)) {
  if (config.clear_radius_cells > config.radius_cells) {
    clear_ = InflateObstacles(free, config.clear_radius_cells);
  }
  // The robot starts from where it stands and, as GridPlanner leaves a start the inflation
  // blocks or boxes in (after a collision, beside a counter), from every free cell within the
  // snap radius, at the straight distance to it.
  std::vector<DistanceSource> sources{{robot, 0.0}};
  for (const Cell& o : DiscOffsets(config.start_snap_cells)) {
    sources.push_back({{robot.x + o.x, robot.y + o.y}, std::hypot(o.x, o.y)});
  }
  field_ = OctileDistanceField(inflated_, sources);
}

FootprintReach::Stand FootprintReach::Best(Cell c) const {
  // Equally short ways (a straight corridor to the frontier) stand nearest the cell: it is seen
  // best from there.
  constexpr double kSame = 1e-9;
  const auto better = [](const Stand& stand, const Stand& than) {
    return stand.distance < than.distance - kSame ||
           (stand.distance < than.distance + kSame && stand.reach < than.reach);
  };
  // Without a preference every reachable stand keeps the clearance asked for.
  const PassabilityGrid& clear = clear_.has_value() ? *clear_ : inflated_;
  Stand best{kUnreachable, 0.0, std::nullopt};
  Stand best_clear = best;
  for (const Cell& o : reach_disc_) {
    const Cell s{c.x + o.x, c.y + o.y};
    if (!inflated_.Contains(s)) continue;
    const double path = field_[inflated_.Index(s)];
    if (path == kUnreachable) continue;
    const double reach = std::hypot(o.x, o.y);
    const Stand stand{path + reach, reach, s};
    if (better(stand, best)) best = stand;
    if (clear.at(s) != 0 && better(stand, best_clear)) best_clear = stand;
  }
  // The distance is the shortest way; the stand keeps the clearance when a clear one reaches.
  if (best_clear.cell) return {best.distance, best_clear.reach, best_clear.cell};
  return best;
}

double FootprintReach::Distance(Cell c) const { return Best(c).distance; }

std::optional<Cell> FootprintReach::StandFor(Cell c) const { return Best(c).cell; }

}  // namespace semnav::planning
