#include "services/launcher/stack_runner.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "services/common/net/host_port.h"
#include "services/launcher/child_process.h"
#include "services/launcher/health_probe.h"
#include "services/launcher/port_check.h"

namespace semnav::launcher {
namespace {

constexpr absl::Duration kPollPeriod = absl::Milliseconds(100);

// One health check; "SERVING", "NOT_SERVING", or the transport error.
std::string CheckHealth(const std::string& address, absl::Duration timeout) {
  ClientOptions plaintext;
  plaintext.address = address;
  absl::StatusOr<std::string> health = ProbeHealth(plaintext, "", timeout);
  if (!health.ok()) return absl::StrCat("UNAVAILABLE (", health.status().message(), ")");
  return *health;
}

std::string DashboardUrl(const std::string& listen) {
  const HostPort address = SplitHostPort(listen).value_or(HostPort{listen, listen});
  std::string host = address.host;
  const std::string& port = address.port;
  if (host.empty() || host == "0.0.0.0") host = "127.0.0.1";
  if (host == "[::]") host = "[::1]";
  return absl::StrCat("http://", host, ":", port, "/");
}

}  // namespace

StackRunner::StackRunner(StackConfig config, std::string bin_dir, RunnerOptions options)
    : config_(std::move(config)), bin_dir_(std::move(bin_dir)), options_(options) {}

StackRunner::~StackRunner() { (void)Stop(); }

absl::Status StackRunner::Launch(Child& child) {
  absl::StatusOr<pid_t> pid = SpawnChild(child.argv, child.output_file);
  if (!pid.ok()) return pid.status();
  child.pid = *pid;
  child.started = absl::Now();
  child.restart_at.reset();
  return absl::OkStatus();
}

absl::Status StackRunner::WaitHealthy(Child& child, absl::Time deadline) {
  std::string health;
  while (true) {
    if (child.health == Health::kGrpc) {
      health = CheckHealth(child.health_target, absl::Milliseconds(500));
      if (health == "SERVING") return absl::OkStatus();
    } else if (child.health == Health::kHttp) {
      const absl::Status http = ProbeHttp(child.health_target, absl::Milliseconds(500));
      if (http.ok()) return absl::OkStatus();
      health = std::string(http.message());
    } else {
      return absl::OkStatus();
    }
    int status = 0;
    if (::waitpid(child.pid, &status, WNOHANG) == child.pid) {
      child.pid = -1;
      return absl::UnavailableError(
          absl::StrCat(child.argv[0], " exited during start-up (", DescribeExit(status), ")"));
    }
    if (absl::Now() > deadline) {
      return absl::DeadlineExceededError(
          absl::StrCat(child.name, " not ready after ", config_.startup_timeout_s, " s: ", health));
    }
    absl::SleepFor(kPollPeriod);
  }
}

void StackRunner::AddDashboard() {
  if (!config_.dashboard.enabled) return;
  const std::string bundle =
      (std::filesystem::path(bin_dir_).parent_path() / "web" / "semnav-dashboard.js").string();
  const std::string node = FindOnPath("node");
  if (node.empty()) {
    notes_.push_back(
        "dashboard: not started: Node.js (`node`) is not on PATH; bash deploy/install-deps.sh "
        "installs it");
    return;
  }
  if (!std::filesystem::exists(bundle)) {
    notes_.push_back(absl::StrCat("dashboard: not started: ", bundle,
                                  " is missing; cmake --build --preset release builds it"));
    return;
  }
  const std::optional<StackConfig::ClientEndpoints> endpoints = config_.ClientEndpointsOf();
  if (!endpoints) {
    notes_.push_back(
        "dashboard: not started: the stack needs gateway, mapping and planning services");
    return;
  }
  Child child;
  child.name = "dashboard";
  child.argv = {node,         bundle,
                "--listen",   config_.dashboard.listen,
                "--gateway",  endpoints->gateway,
                "--mapping",  endpoints->mapping,
                "--planning", endpoints->planning,
                "--robot-id", config_.dashboard.robot_id};
  child.health = Health::kHttp;
  child.health_target = DashboardUrl(config_.dashboard.listen);
  // The proxy prints its bound address as JSON on stdout; the URL line below says it for people.
  child.output_file = (std::filesystem::path(work_dir_) / "dashboard.out").string();
  children_.push_back(std::move(child));
}

void StackRunner::AddSimRobot() {
  if (!options_.sim_robot) return;
  Child child;
  child.name = "sim-robot";
  const SimRobotConfig& robot = config_.sim_robot;
  const StackConfig::ClientEndpoints endpoints = *config_.ClientEndpointsOf();  // checked in Start
  child.argv = {absl::StrCat(bin_dir_, "/semnav-dashboard-sim-robot"),
                "--gateway",
                endpoints.gateway,
                "--mapping",
                endpoints.mapping,
                "--planning",
                endpoints.planning,
                "--robot-id",
                robot.robot_id,
                "--world-seed",
                absl::StrCat(robot.world_seed),
                "--speed",
                absl::StrCat(robot.speed)};
  child.output_file = (std::filesystem::path(work_dir_) / "sim-robot.out").string();
  children_.push_back(std::move(child));
}

std::map<std::string, pid_t> StackRunner::child_pids() const {
  std::map<std::string, pid_t> pids;
  for (const Child& child : children_) pids[child.name] = child.pid;
  return pids;
}

absl::Status StackRunner::Start() {
  absl::StatusOr<StackLock> lock = StackLock::Acquire(StackLockPath(config_));
  if (!lock.ok()) {
    return absl::FailedPreconditionError(
        absl::StrCat(lock.status().message(),
                     "; stop it first, or give this one other ports with --config FILE"));
  }
  lock_.emplace(std::move(*lock));
  for (const StackService& service : config_.services) {
    if (absl::Status free = CheckListenAddressFree(service.listen); !free.ok()) {
      return absl::FailedPreconditionError(
          absl::StrCat(service.name, ": ", free.message(),
                       " (another stack or program?); stop it, or choose other "
                       "ports with --config FILE"));
    }
  }
  // The page is optional: a port taken by another program (a web server on 8080) costs the
  // dashboard, not the stack.
  if (config_.dashboard.enabled) {
    if (absl::Status free = CheckListenAddressFree(config_.dashboard.listen); !free.ok()) {
      notes_.push_back(
          absl::StrCat("dashboard: not started: ", free.message(),
                       "; give it another address (dashboard.listen) with --config FILE"));
      config_.dashboard.enabled = false;
    }
  }
  if (options_.sim_robot && !config_.ClientEndpointsOf()) {
    return absl::InvalidArgumentError(
        "--sim-robot needs the stack's gateway, mapping and planning services");
  }
  state_path_ = StackStatePath(config_);
  work_dir_ =
      absl::StrCat(state_path_, ".d");  // one per stack: a bench runs several in one process
  std::filesystem::create_directories(work_dir_);

  for (const StackService& service : config_.services) {
    const std::string path = absl::StrCat(bin_dir_, "/", service.binary);
    if (::access(path.c_str(), X_OK) != 0) {
      return absl::NotFoundError(
          absl::StrCat("services.", service.name, ".binary: ", path, " not found"));
    }
    Child child;
    child.name = service.name;
    child.argv = {path, "--listen", service.listen};
    if (!service.config.empty()) {
      child.argv.push_back("--config");
      child.argv.push_back(service.config);
    }
    child.health = Health::kGrpc;
    child.health_target = service.listen;
    children_.push_back(std::move(child));
  }
  const size_t service_count = children_.size();
  AddDashboard();
  AddSimRobot();
  const absl::Time deadline = absl::Now() + absl::Seconds(config_.startup_timeout_s);
  // Services first (all at once), then what depends on them, each stage healthy before the next.
  for (size_t i = 0; i < service_count; ++i) {
    if (absl::Status s = Launch(children_[i]); !s.ok()) return s;
  }
  for (size_t i = 0; i < service_count; ++i) {
    if (absl::Status s = WaitHealthy(children_[i], deadline); !s.ok()) return s;
  }
  for (size_t i = service_count; i < children_.size(); ++i) {
    Child& child = children_[i];
    if (absl::Status s = Launch(child); !s.ok()) return s;
    if (absl::Status s = WaitHealthy(child, deadline); !s.ok()) {
      if (child.name != "dashboard") return s;
      // The page is optional: the stack still serves its clients without it.
      notes_.push_back(absl::StrCat("dashboard: not started: ", s.message()));
      if (child.pid > 0) ::kill(child.pid, SIGKILL), ::waitpid(child.pid, nullptr, 0);
      child.pid = -1;
      children_.erase(children_.begin() + static_cast<std::ptrdiff_t>(i));
      --i;
      continue;
    }
    if (child.name == "dashboard") dashboard_url_ = child.health_target;
  }
  for (Child& child : children_) child.backoff_s = config_.restart.initial_backoff_s;
  PublishState();
  return absl::OkStatus();
}

void StackRunner::ReapExited() {
  int status = 0;
  pid_t pid;
  while ((pid = ::waitpid(-1, &status, WNOHANG)) > 0) {
    for (Child& child : children_) {
      if (child.pid != pid) continue;
      child.pid = -1;
      child.last_exit = DescribeExit(status);
      // A child that ran long enough was healthy: its next failure starts the back-off over.
      if (absl::Now() - child.started >= absl::Seconds(config_.restart.stable_after_s)) {
        child.backoff_s = config_.restart.initial_backoff_s;
      }
      child.restart_at = absl::Now() + absl::Seconds(child.backoff_s);
      std::cerr << "semnav up: " << child.name << " exited (" << child.last_exit
                << "); restarting in " << child.backoff_s << " s" << std::endl;
      child.backoff_s = std::min(child.backoff_s * 2, config_.restart.max_backoff_s);
    }
  }
}

void StackRunner::RestartDue() {
  bool changed = false;
  for (Child& child : children_) {
    if (!child.restart_at || absl::Now() < *child.restart_at) continue;
    if (absl::Status s = Launch(child); !s.ok()) {
      std::cerr << "semnav up: cannot restart " << child.name << ": " << s.message() << std::endl;
      child.restart_at = absl::Now() + absl::Seconds(child.backoff_s);
      continue;
    }
    ++child.restarts;
    changed = true;
    std::cerr << "semnav up: restarted " << child.name << " (pid " << child.pid << ", restart "
              << child.restarts << ")" << std::endl;
  }
  if (changed) PublishState();
}

void StackRunner::PublishState() {
  StackState state;
  state.launcher_pid = ::getpid();
  state.dashboard_url = dashboard_url_.value_or("");
  for (const Child& child : children_)
    state.children[child.name] = {child.pid, child.restarts, child.last_exit};
  if (absl::Status s = WriteStackState(state_path_, state); !s.ok())
    std::cerr << "semnav up: " << s.message() << "\n";
}

absl::Status StackRunner::Supervise() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGCHLD);
  while (true) {
    absl::Duration wait = absl::Seconds(1);
    for (const Child& child : children_) {
      if (child.restart_at)
        wait = std::min(wait, std::max(absl::ZeroDuration(), *child.restart_at - absl::Now()));
    }
    const timespec timeout = absl::ToTimespec(wait);
    const int signal_number = sigtimedwait(&signals, nullptr, &timeout);
    if (signal_number == SIGINT || signal_number == SIGTERM) return absl::OkStatus();
    ReapExited();
    RestartDue();
  }
}

absl::Status StackRunner::StopChildren(bool services, absl::Time deadline) {
  for (auto child = children_.rbegin(); child != children_.rend(); ++child) {
    if (child->pid > 0 && (child->health == Health::kGrpc) == services) ::kill(child->pid, SIGTERM);
  }
  absl::Status result = absl::OkStatus();
  for (Child& child : children_) {
    if ((child.health == Health::kGrpc) != services) continue;
    child.restart_at.reset();
    if (child.pid <= 0) continue;
    int status = 0;
    while (::waitpid(child.pid, &status, WNOHANG) != child.pid) {
      if (absl::Now() > deadline) {
        ::kill(child.pid, SIGKILL);
        ::waitpid(child.pid, &status, 0);
        result = absl::DeadlineExceededError(absl::StrCat(child.name, " had to be killed"));
        break;
      }
      absl::SleepFor(absl::Milliseconds(20));
    }
    // Node exits with 143 (128 + SIGTERM) or by the signal itself: both are a clean stop.
    const bool clean =
        (WIFEXITED(status) && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 128 + SIGTERM)) ||
        (WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM && child.health != Health::kGrpc);
    if (result.ok() && !clean) {
      result =
          absl::InternalError(absl::StrCat(child.name, " stopped with ", DescribeExit(status)));
    }
    child.pid = -1;
  }
  return result;
}

absl::Status StackRunner::Stop() {
  // Dependants first, and gone before the services stop: the robot and the page are clients of
  // the services. Signalled together, the robot could see its gateway close the session first
  // and exit with an error, and `semnav up` then reported an unclean stop (web_stack_e2e, once
  // in a few runs: "sim-robot stopped with exit code 1").
  const absl::Time deadline = absl::Now() + absl::Seconds(config_.stop_timeout_s);
  absl::Status result = StopChildren(/*services=*/false, deadline);
  if (absl::Status services = StopChildren(/*services=*/true, deadline); result.ok()) {
    result = services;
  }
  if (!state_path_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(state_path_, ignored);
    std::filesystem::remove(StackLockPath(config_),
                            ignored);  // still held: no one else can take it now
    std::filesystem::remove_all(work_dir_, ignored);
    state_path_.clear();
  }
  return result;
}

absl::Status PrintStatus(const StackConfig& config) {
  const absl::StatusOr<StackState> state = ReadLiveStackState(StackStatePath(config));
  bool all_serving = true;
  for (const StackService& service : config.services) {
    const std::string health = CheckHealth(service.listen, absl::Seconds(2));
    all_serving &= health == "SERVING";
    std::cout << std::left << std::setw(16) << service.name << std::setw(22) << service.listen
              << health;
    if (state.ok() && state->children.contains(service.name)) {
      const ChildState& child = state->children.at(service.name);
      if (child.restarts > 0)
        std::cout << "  restarts " << child.restarts << " (last: " << child.last_exit << ")";
    }
    std::cout << "\n";
  }
  if (config.dashboard.enabled) {
    const std::string url = DashboardUrl(config.dashboard.listen);
    const absl::Status http = ProbeHttp(url, absl::Seconds(2));
    std::cout << std::left << std::setw(16) << "dashboard" << std::setw(22)
              << config.dashboard.listen
              << (http.ok() ? std::string("SERVING ") + url
                            : absl::StrCat("UNAVAILABLE (", http.message(), ")"))
              << "\n";
  }
  if (all_serving) return absl::OkStatus();
  return absl::UnavailableError("not every service is SERVING");
}

}  // namespace semnav::launcher
