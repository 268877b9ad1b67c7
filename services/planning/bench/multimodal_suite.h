#pragma once

#include "nlohmann/json.hpp"

namespace semnav::planning::bench {

// Improved Jump A* on the seed 003 map (800 x 800 cells, 40 x 40 m at 5 cm):
// query time at alpha = beta = 1 (ja_ms_800) and the Table 2 rows
// (fly_m, roll_m, switches, energy_j for beta/alpha = 1, 2.5, 5).
nlohmann::json RunMultiModalSuite();

}  // namespace semnav::planning::bench
