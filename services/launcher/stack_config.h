#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav::launcher {

// One service of the stack as `semnav up` starts it.
struct StackService {
  std::string name;     // e.g. "mapping"
  std::string binary;   // e.g. "semnav-mapping", looked up beside the launcher
  std::string listen;   // host:port
  std::string config;   // absolute path of its YAML, or empty for embedded defaults
};

struct StackConfig {
  std::vector<StackService> services;
  double startup_timeout_s = 20;
  double stop_timeout_s = 10;
};

// The stack from a YAML file (see deploy/local.yaml); relative config paths resolve against
// the file's folder. A service's inline `settings:` (its config file's content) is written
// to <TMPDIR>/semnav-stack-<pid>-<n>/<name>.yaml and handed over as its config.
absl::StatusOr<StackConfig> LoadStackConfig(const std::string& path);
// The embedded default: deploy/local.yaml's content, compiled in at build time.
StackConfig DefaultStackConfig();

}  // namespace semnav::launcher
