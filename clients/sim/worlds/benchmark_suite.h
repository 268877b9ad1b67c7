#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "clients/sim/core/world.h"

namespace semnav::sim {

struct SuiteWorld {
  std::string suite;  // folder: indoor, outdoor, flyroll, houseexpo, fr079
  World world;
};

// The benchmark worlds from every source: 4 homes + 4 offices (indoor), the 3 seed-000
// scenes (outdoor), 2 fly-roll halls, the 2 HouseExpo plans and the FR-079 OctoMap (read
// from `shared_data_dir`). Each world has 5 starts. Same seed -> same worlds.
absl::StatusOr<std::vector<SuiteWorld>> BuildBenchmarkSuite(uint64_t seed,
                                                            const std::string& shared_data_dir);

// Writes <out_dir>/<suite>/<world name>.yaml for every world.
absl::Status WriteBenchmarkSuite(const std::vector<SuiteWorld>& worlds, const std::string& out_dir);

}  // namespace semnav::sim
