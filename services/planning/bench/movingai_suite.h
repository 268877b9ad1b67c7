#pragma once

#include <string>

#include "nlohmann/json.hpp"

namespace semnav::planning::bench {

// Runs A* and JPS on every row of the five Moving AI maps under data_dir
// (movingai-grid/), counting rows whose length differs from the optimum by
// more than 1e-4, and times both planners per map, on `threads` threads.
nlohmann::json RunMovingAiSuite(const std::string& data_dir, int threads);

}  // namespace semnav::planning::bench
