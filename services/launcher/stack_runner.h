#pragma once

#include <sys/types.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/time/time.h"
#include "services/launcher/stack_config.h"
#include "services/launcher/stack_state.h"

namespace semnav::launcher {

struct RunnerOptions {
  bool sim_robot = false;  // also start a simulated robot (semnav up --sim-robot)
};

// Runs a stack as child processes and supervises it, in the manner of systemd's
// Restart=on-failure: start the services and wait for health SERVING, then the dashboard proxy
// (if the stack has one and Node.js is there) and the simulated robot (if asked); restart any
// child that exits by itself after a growing back-off while the others keep running; on
// SIGINT/SIGTERM stop them all (SIGTERM, SIGKILL after stop_timeout_s). Children die with the
// launcher. A second runner of the same stack, or any process on its ports, makes Start fail.
class StackRunner {
 public:
  StackRunner(StackConfig config, std::string bin_dir, RunnerOptions options = {});
  ~StackRunner();

  absl::Status Start();
  // Blocks until SIGINT or SIGTERM (blocked in the calling thread beforehand), restarting
  // children that exit meanwhile. Returns OK.
  absl::Status Supervise();
  // Stops every running child; OK if all exited with code 0.
  absl::Status Stop();

  // "http://127.0.0.1:8080/" once the dashboard serves; nullopt when it was not started.
  const std::optional<std::string>& dashboard_url() const { return dashboard_url_; }
  // Why an optional part (the dashboard) did not start, for the user.
  const std::vector<std::string>& notes() const { return notes_; }
  // Pid of each child by name, -1 once it exited; e.g. to read a service's memory use.
  std::map<std::string, pid_t> child_pids() const;

 private:
  enum class Health { kGrpc, kHttp, kNone };
  struct Child {
    std::string name;
    std::vector<std::string> argv;
    Health health = Health::kNone;
    std::string health_target;  // host:port (gRPC) or URL (HTTP)
    std::string output_file;    // the child's stdout, "" to share ours
    pid_t pid = -1;
    absl::Time started;
    int restarts = 0;
    double backoff_s = 0;
    std::optional<absl::Time> restart_at;
    std::string last_exit;
  };

  absl::Status Launch(Child& child);
  absl::Status WaitHealthy(Child& child, absl::Time deadline);
  // SIGTERM to the gRPC services (`services`) or to the other children, then waits for them
  // until `deadline` (SIGKILL after it); an error names the first that did not stop cleanly.
  absl::Status StopChildren(bool services, absl::Time deadline);
  void ReapExited();
  void RestartDue();
  void PublishState();
  void AddDashboard();
  void AddSimRobot();

  StackConfig config_;
  std::string bin_dir_;
  RunnerOptions options_;
  std::vector<Child> children_;
  std::optional<StackLock> lock_;
  std::string state_path_;
  std::string work_dir_;
  std::optional<std::string> dashboard_url_;
  std::vector<std::string> notes_;
};

// Health of every service of the stack, one line each, with the restarts a running `semnav up`
// made; OK if all are SERVING.
absl::Status PrintStatus(const StackConfig& config);

}  // namespace semnav::launcher
