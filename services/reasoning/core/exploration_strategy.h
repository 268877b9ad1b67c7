// How planning chooses the next exploration goal. Core code compares these values; the names
// ("EROI_UTILITY") exist only for the config file, the journal and the task's status text, and
// the proto enums are converted once in the adapters (gateway_hub, planning_client).
#pragma once

#include <optional>
#include <string_view>

namespace semnav::reasoning {

enum class ExplorationStrategy {
  kNearestFrontier,   // the closest frontier cluster
  kCoverageMax,       // the frontier that uncovers the most unknown cells per metre
  kSemanticFrontier,  // frontiers scored by the task's language and grounding context
  kEroiUtility,       // seed 000's EROI utility over the model's semantic values
};

// "NEAREST_FRONTIER", "COVERAGE_MAX", "SEMANTIC_FRONTIER" or "EROI_UTILITY".
std::string_view ExplorationStrategyName(ExplorationStrategy strategy);
// The strategy of that name; nullopt for any other text.
std::optional<ExplorationStrategy> ParseExplorationStrategy(std::string_view name);

}  // namespace semnav::reasoning
