// Real services for the gateway's contract tests: each started from a YAML config written to a
// fresh folder under the test temp dir.
#pragma once

#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "tests/support/service_process.h"

namespace semnav::reasoning::testing {

// An empty folder TempDir()/<name> (removed first if it exists).
std::string FreshDir(const std::string& name);

// Writes `yaml` to <dir>/<file> and starts `binary` with it as --config.
absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> StartWithConfig(
    const std::string& binary, const std::string& dir, const std::string& file,
    const std::string& yaml);

// semnav-mapping storing maps under <dir>/maps, publishing scene-graph deltas every 20 ms.
absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> StartMapping(
    const std::string& dir);

}  // namespace semnav::reasoning::testing
