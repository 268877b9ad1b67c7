// Test and benchmark fixtures of the gateway: scene graphs from JSON and the fixed fast-path
// instruction set (services/reasoning/testing/fast_path_*.{json,tsv}).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "services/reasoning/core/scene_graph.h"

namespace semnav::reasoning::testing {

// {"objects": [{"id", "label", "attributes", "position": [x, y, z], "score", "detections",
//   "region"}], "relations": [[subject, relation, object, distance]], "regions": [{"id", "name",
//   "objects"}]}
absl::StatusOr<SceneGraph> LoadSceneGraph(const std::string& path);

struct InstructionCase {
  std::string instruction;
  std::optional<int64_t> expected_object;  // nullopt: the fast path must not decide.
};

absl::StatusOr<std::vector<InstructionCase>> LoadInstructionSet(const std::string& path);

// Paths of the shipped fixture files.
std::string FastPathScenePath();
std::string FastPathInstructionsPath();

}  // namespace semnav::reasoning::testing
