// Deterministic synthetic scene graphs for tests and the gateway benchmark: `regions` regions of
// `per_region` objects cycling through COCO labels, "near" relations between neighbours, and one
// red fire extinguisher next to a door in the middle region.
#pragma once

#include <cstdint>

#include "services/reasoning/core/scene_graph.h"

namespace semnav::reasoning::testing {

inline constexpr int64_t kSyntheticTargetId = 1000000;
inline constexpr int64_t kSyntheticDoorId = 1000001;

// Total objects = regions * per_region + 2 (the target and its door).
SceneGraph SyntheticScene(int regions, int per_region, int embedding_dims = 0);

}  // namespace semnav::reasoning::testing
