#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "services/planning/core/cell_grid.h"

namespace semnav::planning {

// One row of a Moving AI .scen file (x = column, y = row).
struct MovingAiScenario {
  int bucket = 0;
  Cell start;
  Cell goal;
  double optimal_length = 0.0;  // 8-connected, no corner cutting
};

// Reads a Moving AI .map ("type octile", height, width, "map", rows);
// '.', 'G', 'S' are passable, everything else blocked.
absl::StatusOr<PassabilityGrid> LoadMovingAiMap(const std::string& path);

// Reads a Moving AI .scen file (version 1, tab separated).
absl::StatusOr<std::vector<MovingAiScenario>> LoadMovingAiScenarios(const std::string& path);

}  // namespace semnav::planning
