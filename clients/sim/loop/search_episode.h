// A search episode for the demo: a generated home the benchmarks never use, and a target the
// robot cannot see from its start, so the gateway has to explore to find it.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/loop/episode_spec.h"

namespace semnav::sim::loop {

// The demo's home: seed 11 of the home generator, named demo_home_11. The mission benchmark
// generates home_N from seeds 1-4 (its default --seed 1), the benchmark suite mixes its seed
// with each world's name, and the smoke episode uses seed 7.
inline constexpr uint64_t kDemoWorldSeed = 11;

// Geodesic distance (l_i) a search target must have: far enough that finding it takes
// exploration, near enough that the demo takes tens of seconds.
inline constexpr double kSearchMinPathM = 4.0;
inline constexpr double kSearchMaxPathM = 12.0;

// World::objects indices of the objects that cover at least one pixel of the robot's camera
// (its height, pitch and intrinsics, any depth) while it turns a full circle on the spot at
// `start`, in 12 steps of 30 degrees (the 160-pixel loop camera sees 63 degrees across).
std::set<int> ObjectsInSightFrom(const World& world, const Scene& scene, const StartPose& start,
                                 const RobotConfig& robot, const SensorConfig& sensors);

struct SearchTarget {
  std::string label;
  double shortest_path_m = 0.0;  // l_i: start to the nearest success point, on `grid`
};

// Labels no instance of which is in `in_sight` and all of whose instances stand on the floor
// (furniture, not an item on top of it), whose success region (within the success
// radius of an instance) is reachable on `grid` from `start` at a path length in
// [min_path_m, max_path_m], and that do not start inside it; sorted by path length.
std::vector<SearchTarget> OutOfSightTargets(const World& world, const GroundTruthGrid& grid,
                                            const Eigen::Vector2d& start,
                                            const std::set<int>& in_sight, double min_path_m,
                                            double max_path_m);

// demo_home_<world_seed>; the first start (in world order) with an out-of-sight floor-standing
// target at 4-12 m by path, turned as the world has it; of those targets, the one nearest by
// path. It is searched for with SEMANTIC_FRONTIER, the gateway's default. NOT_FOUND when no start
// has one.
absl::StatusOr<EpisodeSpec> SearchEpisode(uint64_t world_seed = kDemoWorldSeed);

}  // namespace semnav::sim::loop
