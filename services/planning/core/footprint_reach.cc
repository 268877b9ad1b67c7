#include "services/planning/core/footprint_reach.h"

#include <cmath>

#include "services/planning/core/distance_field.h"
#include "services/planning/core/inflation.h"

namespace semnav::planning {

FootprintReach::FootprintReach(const PassabilityGrid& free, Cell robot,
                               const FootprintReachConfig& config)
    : inflated_(InflateObstacles(free, config.radius_cells)),
      reach_disc_(DiscOffsets(config.reach_cells)) {
  clear_ = config.clear_radius_cells > config.radius_cells
               ? InflateObstacles(free, config.clear_radius_cells)
               : inflated_;
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
  const auto better = [](double d, double reach, const Stand& than, double than_reach) {
    return d < than.distance - kSame || (d < than.distance + kSame && reach < than_reach);
  };
  Stand best{kUnreachable, std::nullopt};
  Stand best_clear{kUnreachable, std::nullopt};
  double best_reach = 0.0, best_clear_reach = 0.0;
  for (const Cell& o : reach_disc_) {
    const Cell s{c.x + o.x, c.y + o.y};
    if (!inflated_.Contains(s)) continue;
    const double path = field_[inflated_.Index(s)];
    if (path == kUnreachable) continue;
    const double reach = std::hypot(o.x, o.y);
    const double d = path + reach;
    if (better(d, reach, best, best_reach)) {
      best = {d, s};
      best_reach = reach;
    }
    if (clear_.at(s) != 0 && better(d, reach, best_clear, best_clear_reach)) {
      best_clear = {d, s};
      best_clear_reach = reach;
    }
  }
  // The distance is the shortest way; the stand keeps the clearance when a clear one reaches.
  if (best_clear.cell) return {best.distance, best_clear.cell};
  return best;
}

double FootprintReach::Distance(Cell c) const { return Best(c).distance; }

std::optional<Cell> FootprintReach::StandFor(Cell c) const { return Best(c).cell; }

}  // namespace semnav::planning
