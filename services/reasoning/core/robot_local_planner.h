// Planner used when no planning service is configured: the robot's own local planner drives to
// the goal (empty path in the command, as the robot session contract allows), and exploration
// falls back to the topological memory's least-explored direction.
#pragma once

#include "absl/status/statusor.h"
#include "services/reasoning/core/navigation_interfaces.h"

namespace semnav::reasoning {

class RobotLocalPlanner : public PathPlanner {
 public:
  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery&) override {
    return std::vector<Eigen::Vector3d>{};
  }
  absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery&) override {
    return absl::NotFoundError("no planning service configured");
  }
};

}  // namespace semnav::reasoning
