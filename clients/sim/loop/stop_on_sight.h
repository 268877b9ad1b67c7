// Where a robot driving a path stops on seeing its target: the task executor's "success in
// view" rule, for scenarios that move the robot along a computed path.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "clients/sim/core/scene.h"
#include "clients/sim/core/world.h"

namespace semnav::sim::loop {

// The robot drives `path` (toward where it believes `target`, an element of world.objects, is)
// and stops at the first point where its camera sees the target within `reach` of its
// footprint: the task executor's stop rule (within reach with the target in view). Seen = a ray
// from the camera, inside the horizontal field of view about the direction of travel and within
// `range`, whose first hit is the target, toward its footprint's centre or a corner pulled 10 %
// inward. Returns the index in `path` (the last one when it never sees it).
size_t StopOnSight(const std::vector<Eigen::Vector2d>& path, const World& world, const Scene& scene,
                   const ObjectInstance& target, double camera_height, double half_fov_rad,
                   double range, double reach);

}  // namespace semnav::sim::loop
