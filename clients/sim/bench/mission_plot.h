// Top-down PNG of one episode: true occupancy, the target's instances, the path, start and end.
#pragma once

#include <string>

#include "absl/status/status.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/loop/episode_spec.h"

namespace semnav::sim::bench {

absl::Status WriteEpisodePlot(const World& world, const GroundTruthGrid& grid, const std::string& target_label,
                              const loop::EpisodeResult& result, const std::string& png_path);

}  // namespace semnav::sim::bench
