#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav::launcher {

// One service of the stack as `semnav up` starts it.
struct StackService {
  std::string name;    // e.g. "mapping"
  std::string binary;  // e.g. "semnav-mapping", looked up beside the launcher
  std::string listen;  // host:port
  std::string config;  // absolute path of its YAML, or empty for embedded defaults
};

// How `semnav up` restarts a child that exited by itself: after initial_backoff_s, doubling up
// to max_backoff_s for each further exit; a child that stayed up stable_after_s starts over.
struct RestartPolicy {
  double initial_backoff_s = 0.5;
  double max_backoff_s = 30;
  double stable_after_s = 60;
};

// The browser dashboard's Node proxy (build/<preset>/web/semnav-dashboard.js), started after the
// services when the stack has a `dashboard:` section.
struct DashboardConfig {
  bool enabled = false;
  std::string listen = "127.0.0.1:8080";
  std::string robot_id = "sim-robot";  // robot the page shows
};

// The simulated robot of `semnav up --sim-robot` (semnav-dashboard-sim-robot in a generated home).
struct SimRobotConfig {
  std::string robot_id = "sim-robot";
  int world_seed = 7;
  double speed = 1.0;  // simulated seconds per wall second
};

struct StackConfig {
  std::vector<StackService> services;
  double startup_timeout_s = 20;
  double stop_timeout_s = 10;
  RestartPolicy restart;
  DashboardConfig dashboard;
  SimRobotConfig sim_robot;
  // Where the services' inline settings were written (see LoadStackConfig); the folder is
  // removed with the last copy of this config. nullptr when no service has inline settings.
  std::shared_ptr<const std::filesystem::path> settings_folder;

  // The listen address of the service named `name`, or "" when the stack has none.
  std::string AddressOf(const std::string& name) const;
  // What the dashboard and the simulated robot talk to; nullopt unless the stack has all three.
  struct ClientEndpoints {
    std::string gateway;
    std::string mapping;
    std::string planning;
  };
  std::optional<ClientEndpoints> ClientEndpointsOf() const;
};

// The stack from a YAML file (see deploy/local.yaml); relative config paths resolve against
// the file's folder. A service's inline `settings:` (its config file's content) is written
// to <TMPDIR>/semnav-stack-<pid>-<n>/<name>.yaml and handed over as its config; the folder
// lives as long as the returned config (or a copy of it).
absl::StatusOr<StackConfig> LoadStackConfig(const std::string& path);
// The embedded default: deploy/local.yaml's content, compiled in at build time.
StackConfig DefaultStackConfig();

}  // namespace semnav::launcher
