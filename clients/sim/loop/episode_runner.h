// One closed-loop episode over the real contracts: the simulated robot holds a gateway session
// and streams frames to mapping, the operator API gets the instruction, the robot executes the
// gateway's commands in simulated time until the task ends or the step budget runs out; then
// the episode is scored with seed 004's metrics (l_i from the planning service).
#pragma once

#include <functional>

#include "absl/status/statusor.h"
#include "clients/sim/loop/episode_spec.h"
#include "semnav/reasoning/v1/operator.pb.h"

namespace semnav::sim::loop {

// Called after every step (progress display); may be empty.
using StepObserver = std::function<void(int step, const EpisodeResult& so_far)>;

// The strategy an episode's label names ("EROI_UTILITY"); UNSPECIFIED for another label
// ("smoke"), which leaves the gateway's configured default.
reasoning::v1::ExplorationStrategy RequestedStrategy(const std::string& label);

absl::StatusOr<EpisodeResult> RunEpisode(const EpisodeSpec& spec, const Endpoints& endpoints,
                                         const StepObserver& observer = {});

}  // namespace semnav::sim::loop
