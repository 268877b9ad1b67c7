#pragma once

#include <string>

#include "nlohmann/json.hpp"

namespace semnav::planning::bench {

// PlanPath's 2D planner (GridPlanner: inflation, start handling, clearance) on the first rows of
// two indoor-like Moving AI maps at 5 cm cells, clearance off (JPS) against on (A* over the
// Nav2-style cost): time per query and how much longer the kept-clear paths are.
nlohmann::json RunGridPlannerSuite(const std::string& data_dir);

}  // namespace semnav::planning::bench
