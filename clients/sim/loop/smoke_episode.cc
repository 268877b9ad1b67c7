#include "clients/sim/loop/smoke_episode.h"

#include "absl/strings/str_cat.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/loop/target_choice.h"
#include "clients/sim/worlds/indoor_generator.h"

namespace semnav::sim::loop {

absl::StatusOr<EpisodeSpec> SmokeEpisode(uint64_t world_seed) {
  EpisodeSpec spec;
  spec.world = GenerateIndoor(absl::StrCat("smoke_home_", world_seed), IndoorOptions{}, world_seed);
  RasterOptions raster;
  raster.robot_radius = RobotConfig::ForModality(Modality::kGround).radius;
  const GroundTruthGrid grid = RasterizeOccupancy(spec.world, raster);
  for (int i = 0; i < static_cast<int>(spec.world.starts.size()); ++i) {
    StartPose& start = spec.world.starts[i];
    // The gateway's NAVIGATE goal sits 1 m short of the target's mapped centre and APPROACH
    // 0.5 m: the free corridor reaches 0.6 m from the footprint, so the 1 m success radius is
    // within reach with room for mapping error (an item in the middle of a table is not).
    const std::optional<TargetChoice> choice =
        PickInSightTarget(spec.world, grid, start.position.head<2>(), 1.5, 3.5, 0.6);
    if (!choice.has_value()) continue;
    start.yaw = choice->yaw_to_target;
    spec.start_index = i;
    spec.target = choice->label;
    spec.strategy = "smoke";
    spec.max_steps = 200;
    spec.seed = world_seed;
    return spec;
  }
  return absl::NotFoundError(absl::StrCat("no in-sight target in ", spec.world.name));
}

}  // namespace semnav::sim::loop
