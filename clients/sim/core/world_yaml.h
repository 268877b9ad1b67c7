#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "clients/sim/core/world.h"

// World files (YAML, format in docs/simulation.md). Errors are INVALID_ARGUMENT naming the
// field path (InvalidField: the field also travels as the status payload); a missing file or
// folder is NOT_FOUND. Besides the format, the loader rejects object labels that are not
// objects of the reasoning lexicon (services/common/lexicon/lexicon.tsv), geometry, rooms and
// starts outside the bounds, and starts where the robot's body (RobotConfig of the start's
// modality) touches a solid; FAILED_PRECONDITION when the lexicon cannot be read.
namespace semnav::sim {

absl::StatusOr<World> ParseWorldYaml(const std::string& text);
absl::StatusOr<World> LoadWorldFile(const std::string& path);
// Every *.yaml file of a folder, sorted by file name: a benchmark suite.
absl::StatusOr<std::vector<World>> LoadSuite(const std::string& directory);

std::string WorldToYaml(const World& world);
absl::Status SaveWorldFile(const World& world, const std::string& path);

}  // namespace semnav::sim
