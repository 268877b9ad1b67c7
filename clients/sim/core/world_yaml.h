#ifndef SEMNAV_CLIENTS_SIM_CORE_WORLD_YAML_H_
#define SEMNAV_CLIENTS_SIM_CORE_WORLD_YAML_H_

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "clients/sim/core/world.h"

// World files (YAML, format in docs/simulation.md). Errors are INVALID_ARGUMENT naming the
// field path; a missing file or folder is NOT_FOUND.
namespace semnav::sim {

absl::StatusOr<World> ParseWorldYaml(const std::string& text);
absl::StatusOr<World> LoadWorldFile(const std::string& path);
// Every *.yaml file of a folder, sorted by file name: a benchmark suite.
absl::StatusOr<std::vector<World>> LoadSuite(const std::string& directory);

std::string WorldToYaml(const World& world);
absl::Status SaveWorldFile(const World& world, const std::string& path);

}  // namespace semnav::sim

#endif  // SEMNAV_CLIENTS_SIM_CORE_WORLD_YAML_H_
