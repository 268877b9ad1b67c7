#pragma once

#include "nlohmann/json.hpp"

namespace semnav::planning::bench {

// The anchor of seed 003 sec. 4.2: OMPL's RRT* (default parameters, path
// length objective) on the same 40 x 40 m map and query as the improved
// Jump A*, run for `seconds`; the path's length and its energy under the
// same model (flying over obstacle cells, rolling elsewhere) side by side
// with Jump A* at alpha = beta = 1.
nlohmann::json RunRrtStarSuite(double seconds);

}  // namespace semnav::planning::bench
