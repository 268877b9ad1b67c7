#include "clients/sim/loop/search_episode.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/camera_model.h"
#include "clients/sim/core/episode_metrics.h"
#include "clients/sim/core/view_renderer.h"
#include "clients/sim/loop/shortest_path.h"
#include "clients/sim/worlds/indoor_generator.h"

namespace semnav::sim::loop {
namespace {

constexpr int kLookAroundHeadings = 12;
// Sight is line of sight, not the depth sensor's 8 m: an object in plain view across a large
// room is in sight even if the detector would need a step closer.
constexpr double kSightRangeM = 100.0;
// The furnisher puts items on top of a support at the support's top; floor furniture at 0.
constexpr double kFloorStandingMaxBaseM = 0.1;

}  // namespace

std::set<int> ObjectsInSightFrom(const World& world, const Scene& scene, const StartPose& start,
                                 const RobotConfig& robot, const SensorConfig& sensors) {
  std::set<int> seen;
  const Eigen::Vector3d camera_at = start.position + Eigen::Vector3d(0.0, 0.0, robot.camera_height);
  for (int h = 0; h < kLookAroundHeadings; ++h) {
    const double yaw = start.yaw + 2.0 * M_PI * h / kLookAroundHeadings;
    const RenderedView view =
        RenderView(scene, sensors.intrinsics, CameraPoseInWorld(camera_at, yaw, robot.camera_pitch),
                   sensors.min_range, kSightRangeM);
    for (const int32_t surface : view.surface) {
      if (surface < 0) continue;  // floor, ceiling, nothing
      const int object = scene.solids()[static_cast<size_t>(surface)].object_index;
      if (object >= 0 && object < static_cast<int>(world.objects.size())) seen.insert(object);
    }
  }
  return seen;
}

std::vector<SearchTarget> OutOfSightTargets(const World& world, const GroundTruthGrid& grid,
                                            const Eigen::Vector2d& start,
                                            const std::set<int>& in_sight, double min_path_m,
                                            double max_path_m) {
  std::set<std::string> labels;
  for (const ObjectInstance& object : world.objects) labels.insert(object.label);
  for (const int index : in_sight) labels.erase(world.objects[static_cast<size_t>(index)].label);
  // Small items on other furniture (a teddy bear on a bed, a toothbrush on a sink) need the
  // detector close by and make the search a lottery: the target is furniture on the floor.
  for (const ObjectInstance& object : world.objects) {
    if (object.box.base_z >= kFloorStandingMaxBaseM) labels.erase(object.label);
  }
  std::vector<SearchTarget> targets;
  for (const std::string& label : labels) {
    // An episode that starts in the success region has l_i = 0, which SPL cannot score.
    if (DistanceToNearestInstance(world, label, start) <= kDefaultSuccessRadius) continue;
    const std::optional<NearestGoal> goal =
        NearestSuccessPoint(world, grid, start, label, kDefaultSuccessRadius);
    if (!goal.has_value() || goal->length_m < min_path_m || goal->length_m > max_path_m) continue;
    targets.push_back(SearchTarget{label, goal->length_m});
  }
  std::sort(targets.begin(), targets.end(), [](const SearchTarget& a, const SearchTarget& b) {
    return a.shortest_path_m < b.shortest_path_m;
  });
  return targets;
}

absl::StatusOr<EpisodeSpec> SearchEpisode(uint64_t world_seed) {
  EpisodeSpec spec;
  spec.world = GenerateIndoor(absl::StrCat("demo_home_", world_seed), IndoorOptions{}, world_seed);
  const Scene scene = Scene::Build(spec.world);
  for (int i = 0; i < static_cast<int>(spec.world.starts.size()); ++i) {
    const StartPose& start = spec.world.starts[i];
    if (start.modality != Modality::kGround) continue;
    // The camera and raster the episode runner gives this robot, so "out of sight" and l_i are
    // what the episode itself will see and score.
    RobotConfig robot = RobotConfig::ForModality(start.modality);
    robot.camera_pitch = spec.ground_camera_pitch;
    const GroundTruthGrid grid =
        RasterizeOccupancy(spec.world, BodyRaster(robot, start.position.z()));
    const std::vector<SearchTarget> targets =
        OutOfSightTargets(spec.world, grid, start.position.head<2>(),
                          ObjectsInSightFrom(spec.world, scene, start, robot, spec.sensors),
                          kSearchMinPathM, kSearchMaxPathM);
    if (targets.empty()) continue;
    spec.start_index = i;
    spec.target = targets.front().label;
    spec.strategy = "SEMANTIC_FRONTIER";
    spec.seed = world_seed;
    return spec;
  }
  return absl::NotFoundError(
      absl::StrCat("no out-of-sight target 4-12 m away in ", spec.world.name));
}

}  // namespace semnav::sim::loop
