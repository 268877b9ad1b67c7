#include "services/planning/core/coverage_goal.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "services/planning/core/alternative_point.h"
#include "services/planning/core/reachability.h"

namespace semnav::planning {

std::optional<Cell> CoverageMaxGoal(const PassabilityGrid& free, Cell robot, double yaw_rad,
                                    const CoverageGoalConfig& config) {
  const std::vector<uint8_t> reachable = ReachableFrom(free, robot);
  const double k = std::max(free.width(), free.height());
  const double reach = std::sqrt(2.0) * k / 2.0;
  const int turns = static_cast<int>(std::ceil(std::numbers::pi / config.turn_step_rad));
  for (int i = 0; i <= 2 * turns; ++i) {
    // 0, +1, -1, +2, -2, ... turn steps away from the heading.
    const int side = (i + 1) / 2 * (i % 2 == 1 ? 1 : -1);
    const double yaw = yaw_rad + side * config.turn_step_rad;
    const Cell target{std::clamp(static_cast<int>(std::lround(robot.x + reach * std::cos(yaw))), 0,
                                 free.width() - 1),
                      std::clamp(static_cast<int>(std::lround(robot.y + reach * std::sin(yaw))), 0,
                                 free.height() - 1)};
    // The farthest reachable cell on the ray towards the boundary point, so
    // an obstacle on the boundary itself does not discard the direction.
    std::optional<Cell> best;
    for (const Cell& c : LineCells(robot, target)) {
      if (reachable[free.Index(c)] != 0) best = c;
    }
    if (best && !(*best == robot)) return best;
  }
  return std::nullopt;
}

}  // namespace semnav::planning
