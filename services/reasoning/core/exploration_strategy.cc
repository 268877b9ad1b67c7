#include "services/reasoning/core/exploration_strategy.h"

#include <array>
#include <utility>

namespace semnav::reasoning {
namespace {

constexpr std::array<std::pair<ExplorationStrategy, std::string_view>, 4> kNames = {{
    {ExplorationStrategy::kNearestFrontier, "NEAREST_FRONTIER"},
    {ExplorationStrategy::kCoverageMax, "COVERAGE_MAX"},
    {ExplorationStrategy::kSemanticFrontier, "SEMANTIC_FRONTIER"},
    {ExplorationStrategy::kEroiUtility, "EROI_UTILITY"},
}};

}  // namespace

std::string_view ExplorationStrategyName(ExplorationStrategy strategy) {
  for (const auto& [value, name] : kNames) {
    if (value == strategy) return name;
  }
  return "";
}

std::optional<ExplorationStrategy> ParseExplorationStrategy(std::string_view name) {
  for (const auto& [value, known] : kNames) {
    if (known == name) return value;
  }
  return std::nullopt;
}

}  // namespace semnav::reasoning
