// The services a closed-loop episode talks to (mapping, planning, gateway), started with the
// launcher's StackRunner from a bin folder, wired to each other through generated configs.
#pragma once

#include <sys/types.h>

#include <map>
#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "clients/sim/loop/episode_spec.h"
#include "services/launcher/stack_runner.h"

namespace semnav::sim::loop {

struct SimStackOptions {
  std::string bin_dir;     // folder holding semnav-mapping, semnav-planning, semnav-gateway
  std::string work_dir;    // configs and the mapping store go here (created)
  bool free_ports = true;  // false: the deploy/local.yaml ports (gateway 50050, ...)
  // A semnav-model-proxy config (YAML) to run a model proxy in the stack and point the gateway
  // at it (gateway.model_proxy.address); empty = no model, the gateway resolves on its fast path
  // only.
  std::string model_proxy_config;
  // The episode budget in simulated seconds, given to the gateway's executor (executor.
  // time_budget_s) so its endgame knows when the last steps come; 0 = no budget.
  double task_time_budget_s = 0.0;
  // Run semnav-relocalization and the gateway's relocalization loop (gateway.relocalization;
  // the drift and kidnapped groups of the mission bench).
  bool relocalization = false;
  // With relocalization: mapping fills the landmark map the gateway relocalizes in ("live",
  // pushed every 0.05 s of wall time) instead of the episode's oracle map under the robot's id.
  bool mapping_landmarks = false;
};

class SimStack {
 public:
  static absl::StatusOr<std::unique_ptr<SimStack>> Start(const SimStackOptions& options);
  ~SimStack();

  const std::string& gateway_address() const { return gateway_; }
  const std::string& mapping_address() const { return mapping_; }
  const std::string& planning_address() const { return planning_; }
  // Fresh channels to the three services.
  Endpoints endpoints() const;
  // Pid of each service process by name ("mapping", "planning", "gateway", ...).
  std::map<std::string, pid_t> service_pids() const { return runner_->child_pids(); }

 private:
  SimStack() = default;
  std::unique_ptr<semnav::launcher::StackRunner> runner_;
  std::string gateway_, mapping_, planning_;
  std::string relocalization_;  // empty = not run
};

}  // namespace semnav::sim::loop
