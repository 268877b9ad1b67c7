// Prompts of the UAV/open-space search (seed 000): the "recognition-evaluation-transfer" VLM
// prompt of Fig. 5 with zero-shot target replacement (eq. 15-16), and the region-scoring LLM
// prompt of Algorithm 2 with its answer parser.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav::reasoning {

// The Fig. 5 prompt for `target`. Eq. 15-16 keep the logic and replace only the target; the
// template substitutes the target deterministically instead of asking an LLM to rewrite it, which
// satisfies Logic(P_new) = Logic(P_old) and Target(P_new) = T_new by construction.
std::string BuildSearchPrompt(std::string_view target);

// Algorithm 2, step 3a: the descriptions collected in one region unit, asking for a score in [-5,
// 5].
std::string BuildRegionScorePrompt(std::string_view target,
                                   const std::vector<std::string>& descriptions);

// The first integer in `answer`; INVALID_ARGUMENT if there is none or it is outside [-5, 5].
absl::StatusOr<int> ParseRegionScore(std::string_view answer);

}  // namespace semnav::reasoning
