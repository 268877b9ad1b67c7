#include "clients/sim/loop/target_choice.h"

#include <cmath>

#include "clients/sim/core/episode_metrics.h"

namespace semnav::sim::loop {
namespace {

bool FreeAt(const GroundTruthGrid& grid, const Eigen::Vector2d& p) {
  const std::optional<Eigen::Vector2i> cell = grid.CellOf(p);
  return cell.has_value() && grid.at(cell->x(), cell->y()) == 0;
}

}  // namespace

std::optional<TargetChoice> PickInSightTarget(const World& world, const GroundTruthGrid& grid,
                                              const Eigen::Vector2d& start, double min_m,
                                              double max_m, double standoff_m) {
  std::optional<TargetChoice> best;
  for (int i = 0; i < static_cast<int>(world.objects.size()); ++i) {
    const ObjectInstance& object = world.objects[i];
    const Eigen::Vector2d offset = object.box.center - start;
    const double distance = offset.norm();
    if (distance < min_m || distance > max_m || (best && distance >= best->distance_m)) continue;
    if (DistanceToNearestInstance(world, object.label, start) < min_m) continue;
    // Walk the corridor up to the standoff point in front of the footprint's bounding circle.
    const double reach = distance - object.box.size.head<2>().norm() / 2.0 - standoff_m;
    bool free = reach > 0.0;
    for (double s = 0.0; free && s <= reach; s += grid.resolution) {
      free = FreeAt(grid, start + offset.normalized() * s);
    }
    if (free) best = TargetChoice{i, object.label, distance, std::atan2(offset.y(), offset.x())};
  }
  return best;
}

}  // namespace semnav::sim::loop
