#pragma once

#include "services/relocalization/core/relocalizer.h"
#include "services/relocalization/eval/baseline.h"
#include "services/relocalization/eval/metrics.h"
#include "services/relocalization/eval/scenario.h"

namespace semnav::relocalization::bench {

// Both methods on every keyframe of one scenario, timed per call (query indexing included).
struct Comparison {
  eval::MethodSummary method;
  eval::MethodSummary baseline;
};

Comparison RunComparison(const eval::Scenario& scenario, const RelocalizationParams& params,
                         const eval::BaselineParams& baseline, const eval::SuccessBounds& bounds);

}  // namespace semnav::relocalization::bench
