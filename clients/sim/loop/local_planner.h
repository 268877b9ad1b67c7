// The robot's own planner for navigate commands that come without a path: A* from the planning
// service on the live map that this robot's frames built (unknown space counts as free, the
// usual optimistic assumption for exploration goals).
#pragma once

#include <grpcpp/channel.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav::sim::loop {

// Positions from just after `from` up to the (possibly adjusted) goal.
using LocalPlanFn = std::function<absl::StatusOr<std::vector<Eigen::Vector2d>>(
    const Eigen::Vector2d& from, const Eigen::Vector2d& to)>;

// Plans through `planning` (which reads mapping's live map). `robot_radius` inflates obstacles.
LocalPlanFn LiveMapPlanner(const std::shared_ptr<grpc::Channel>& planning, double robot_radius);

}  // namespace semnav::sim::loop
