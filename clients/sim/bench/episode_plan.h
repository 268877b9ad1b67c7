// Which episodes a mission benchmark runs: worlds, starts and targets, fixed by the seed so
// every strategy gets the same ones.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "clients/sim/loop/episode_spec.h"

namespace semnav::sim::bench {

// Episodes per report group (ReportGroup): a group's episodes use the worlds that have a start
// of its modality: ground = indoor, uav = outdoor, fly_roll = flyroll.
struct EpisodeCounts {
  int indoor = 4;
  int outdoor = 0;
  int flyroll = 0;
  // Losing the pose (docs/simulation.md): the first `drift` indoor episodes again with odometry
  // drift at the simulator's default noise, the localizer model and the relocalization loop
  // ("drift" group); the first `kidnapped` again with drift and a kidnap as well ("kidnapped").
  int drift = 0;
  int kidnapped = 0;
};

// Per group, episode i uses world i mod W (of the worlds with a start of the group's modality and
// objects), that world's start (i / W) mod S of the modality, and one of the world's object
// labels chosen by (seed, group, i), drawn again while the label cannot be scored: unreachable
// from the start on the body's true raster, or the start already inside its success region
// (l_i must exist and be > 0; SuccessRegion). After 4 x labels draws the labels are tried in
// name order; when none can be scored the episode is left out and `unscorable` (if given) gets
// a line saying which world and start. Every fourth episode (i mod 4 = 3) names its target in
// Chinese (ChineseName). Groups come in the order indoor, outdoor, flyroll.
std::vector<loop::EpisodeSpec> PlanEpisodes(const std::vector<World>& worlds,
                                            const EpisodeCounts& counts, uint64_t seed,
                                            std::vector<std::string>* unscorable = nullptr,
                                            const loop::KidnapConfig& kidnap = {});

}  // namespace semnav::sim::bench
