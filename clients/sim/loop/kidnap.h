// Kidnapped-robot episodes: where the robot is carried, drawn when it happens.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/odometry.h"
#include "clients/sim/core/rng.h"

namespace semnav::sim::loop {

struct KidnapConfig {
  double at_s = 60.0;  // simulated seconds into the episode
  // The destination: a free cell of the body's true raster that the robot reaches from where it
  // stands, min..max from there, and within max_from_path_m of a place it truly went. The
  // kidnapped-robot problem asks for a pose on a map the robot has: carried to a place it never
  // saw, nothing it drew can answer (4 of 19 lost robots before 2026-12-01).
  double min_distance_m = 2.0;
  double max_distance_m = 5.0;
  double max_from_path_m = 1.0;
};

// One destination, uniform over the qualifying cells (by `rng`), with a heading uniform in
// [-pi, pi) and the robot's height; nullopt when no cell qualifies (or the robot's cell is
// occupied on the raster). `path` holds the robot's true positions so far.
std::optional<Pose> KidnapDestination(const GroundTruthGrid& grid, const Pose& robot,
                                      const std::vector<Eigen::Vector2d>& path,
                                      const KidnapConfig& config, Rng& rng);

}  // namespace semnav::sim::loop
