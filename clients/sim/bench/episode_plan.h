// Which episodes a mission benchmark runs: worlds, starts and targets, fixed by the seed so
// every strategy gets the same ones.
#pragma once

#include <cstdint>
#include <vector>

#include "clients/sim/loop/episode_spec.h"

namespace semnav::sim::bench {

// Episode i uses world i mod W, that world's ground-robot start (i / W) mod S, and one of the
// world's object labels chosen by (seed, i). Worlds without ground starts or objects are skipped.
std::vector<loop::EpisodeSpec> PlanEpisodes(const std::vector<World>& worlds, int episodes, uint64_t seed);

}  // namespace semnav::sim::bench
