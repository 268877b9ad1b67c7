// Services the executor needs, implemented by the server over gRPC (planning) and by fakes in
// tests. Calls are synchronous with the implementation's own deadline.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "services/reasoning/core/robot_types.h"

namespace semnav::reasoning {

// One path request. The robot's modality decides the search: 2D for ground robots, the
// multi-modal (roll + fly, seed 003) search for fly-roll robots.
struct PathQuery {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // map frame, metres
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();   // map frame, metres
  bool multi_modal = false;                         // fly-roll robot
  double robot_radius_m = 0.0;                      // footprint inflation; 0 = point robot
  // Extra inflation the path should keep beyond the footprint when the robot's own position
  // allows it (Nav2 inflates past the inscribed radius); dropped when it would inflate the start.
  double clearance_m = 0.0;
  // Seed 004 alternative point: when the goal is in or behind an obstacle, plan to the free point
  // nearest it on the line from here to the goal. Unset = the goal must be reachable as given.
  std::optional<Eigen::Vector3d> alternative_from;
  // > 0: a goal in or walled in by obstacles moves to the reachable free point nearest it within
  // this distance (an object's surroundings); 0 = the gateway's configured tolerance.
  double goal_tolerance_m = 0.0;
  // Planning may answer from a live grid it fetched this long ago (wall time); 0 = a grid fetched
  // for this call. The gateway sets it per robot session (PerTaskPathPlanner).
  int live_map_max_age_ms = 0;
  // Points the robot ran into on its way (map frame): obstacles the map may lack.
  std::vector<Eigen::Vector3d> contacts{};
};

// One exploration request: where the robot is and which goals are spent (it failed to reach
// them, or reached and scanned them already). Planning skips frontiers within
// `excluded_radius_m` of an excluded goal, as explore_lite blacklists frontiers it could not
// reach, so exploration moves on.
struct ExplorationQuery {
  RobotPose pose;
  std::vector<Eigen::Vector3d> excluded_goals;  // map frame, metres
  double excluded_radius_m = 0.0;
  RobotPlatform platform = RobotPlatform::kUnspecified;  // planning picks its rule by it
  // The goal the robot is driving to: planning answers it again (its nearest frontier cell)
  // while its frontier within keep_radius_m is open; unset = the strategy's best.
  std::optional<Eigen::Vector3d> keep_goal;
  double keep_radius_m = 0.0;   // 0 = planning's 1 m
  int live_map_max_age_ms = 0;  // as PathQuery's
  // A ground robot's footprint and path clearance, as PathQuery's: planning answers a cell the
  // footprint stands on, reached as PlanPath reaches it. 0 = a point robot (a frontier cell).
  double robot_radius_m = 0.0;
  double clearance_m = 0.0;
};

// Horizontal length of the way from `from` along `path` (metres).
double HorizontalLength(const Eigen::Vector3d& from, const std::vector<Eigen::Vector3d>& path);

// A dependency of the planner ("planning", or "mapping" behind it) is unreachable or timed out:
// UNAVAILABLE naming it, so the executor pauses the task instead of driving blind.
absl::Status DependencyUnavailableError(absl::string_view dependency, absl::string_view detail);
// The dependency an UNAVAILABLE status names; "planning" when it names none.
std::string UnavailableDependency(const absl::Status& status);

class PathPlanner {
 public:
  virtual ~PathPlanner() = default;
  // Waypoints from start to the planned goal (the last one; an empty list lets the robot plan
  // locally). Typed failures: FAILED_PRECONDITION = the goal is occupied (retry with
  // alternative_from), NOT_FOUND = no path (explore instead), UNAVAILABLE = a dependency is gone
  // (DependencyUnavailableError: the task pauses); any other error is transient.
  virtual absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) = 0;
  // Next exploration goal (the planner's configured strategy, frontier based); NOT_FOUND when the
  // map has no frontier left that is not excluded; UNAVAILABLE as for Plan.
  virtual absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery& query) = 0;
};

}  // namespace semnav::reasoning
