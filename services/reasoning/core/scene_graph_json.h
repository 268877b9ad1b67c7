// Compact JSON of a scene graph as sent to the model (ids, labels, rounded positions, relations,
// regions), and the token estimate used to measure ESCA's saving.
#pragma once

#include <string>

#include "services/reasoning/core/scene_graph.h"

namespace semnav::reasoning {

std::string SceneGraphToPromptJson(const SceneGraph& graph);
// Rough model token count: one token per 4 bytes of prompt text (the usual BPE rule of thumb);
// only ratios of it are reported.
int EstimateTokens(const std::string& text);

}  // namespace semnav::reasoning
