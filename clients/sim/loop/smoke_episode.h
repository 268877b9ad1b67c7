// A short indoor episode whose target is in sight: a generated home, the first start, turned to
// face the nearest object with a free straight approach. Shared by the smoke tests and the
// dashboard's simulated robot; the demo searches instead (search_episode.h).
#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "clients/sim/loop/episode_spec.h"

namespace semnav::sim::loop {

// NOT_FOUND when the generated home has no object 1.5-3.5 m from a start with a free approach.
absl::StatusOr<EpisodeSpec> SmokeEpisode(uint64_t world_seed);

}  // namespace semnav::sim::loop
