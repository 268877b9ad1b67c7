// Top-down PNG of one episode: true occupancy, the target's instances, the path, start and end.
#pragma once

#include <string>

#include "absl/status/status.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/loop/episode_spec.h"

namespace semnav::sim::bench {

absl::Status WriteEpisodePlot(const World& world, const GroundTruthGrid& grid,
                              const std::string& target_label, const loop::EpisodeResult& result,
                              const std::string& png_path);

// The same plot for a search (the demo): free space the robot's map never observed is tinted
// blue-grey (`explored`: same layout as `grid`, nonzero = observed), and every object's footprint
// is drawn, green and named when the robot detected it (result.seen_objects), light grey otherwise;
// a legend sits under the map.
absl::Status WriteExplorationPlot(const World& world, const GroundTruthGrid& grid,
                                  const GroundTruthGrid& explored, const std::string& target_label,
                                  const loop::EpisodeResult& result, const std::string& png_path);

}  // namespace semnav::sim::bench
