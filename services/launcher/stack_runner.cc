#include "services/launcher/stack_runner.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <iomanip>
#include <iostream>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "services/launcher/health_probe.h"

namespace semnav::launcher {
namespace {

// One health check; "SERVING", "NOT_SERVING", or the transport error.
std::string CheckHealth(const std::string& address, absl::Duration timeout) {
  ClientOptions plaintext;
  plaintext.address = address;
  absl::StatusOr<std::string> health = ProbeHealth(plaintext, "", timeout);
  if (!health.ok()) return absl::StrCat("UNAVAILABLE (", health.status().message(), ")");
  return *health;
}

}  // namespace

StackRunner::StackRunner(StackConfig config, std::string bin_dir)
    : config_(std::move(config)), bin_dir_(std::move(bin_dir)) {}

StackRunner::~StackRunner() { (void)Stop(); }

absl::Status StackRunner::Start() {
  for (const StackService& service : config_.services) {
    const std::string path = absl::StrCat(bin_dir_, "/", service.binary);
    if (::access(path.c_str(), X_OK) != 0) {
      (void)Stop();
      return absl::NotFoundError(absl::StrCat("services.", service.name, ".binary: ", path, " not found"));
    }
    std::vector<std::string> args = {path, "--listen", service.listen};
    if (!service.config.empty()) {
      args.push_back("--config");
      args.push_back(service.config);
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
      // The children take SIGINT/SIGTERM from us only, not from the terminal's process group.
      ::setpgid(0, 0);
      sigset_t none;
      sigemptyset(&none);
      pthread_sigmask(SIG_SETMASK, &none, nullptr);
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(path.c_str(), argv.data());
      ::_exit(127);
    }
    children_.push_back({service, pid});
  }
  const absl::Time deadline = absl::Now() + absl::Seconds(config_.startup_timeout_s);
  for (const Child& child : children_) {
    std::string health;
    while ((health = CheckHealth(child.service.listen, absl::Milliseconds(500))) != "SERVING") {
      int status = 0;
      if (::waitpid(child.pid, &status, WNOHANG) == child.pid) {
        for (Child& c : children_) {
          if (c.pid == child.pid) c.pid = -1;
        }
        (void)Stop();
        return absl::UnavailableError(absl::StrCat(child.service.binary, " exited during start-up"));
      }
      if (absl::Now() > deadline) {
        (void)Stop();
        return absl::DeadlineExceededError(
            absl::StrCat(child.service.binary, " not SERVING after ", config_.startup_timeout_s, " s: ", health));
      }
      absl::SleepFor(absl::Milliseconds(100));
    }
  }
  return absl::OkStatus();
}

absl::Status StackRunner::WaitForStopRequest() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGCHLD);
  while (true) {
    int signal_number = 0;
    sigwait(&signals, &signal_number);
    if (signal_number != SIGCHLD) return absl::OkStatus();
    for (Child& child : children_) {
      int status = 0;
      if (child.pid > 0 && ::waitpid(child.pid, &status, WNOHANG) == child.pid) {
        child.pid = -1;
        return absl::AbortedError(absl::StrCat(child.service.binary, " exited unexpectedly (status ", status, ")"));
      }
    }
  }
}

absl::Status StackRunner::Stop() {
  for (const Child& child : children_) {
    if (child.pid > 0) ::kill(child.pid, SIGTERM);
  }
  const absl::Time deadline = absl::Now() + absl::Seconds(config_.stop_timeout_s);
  absl::Status result = absl::OkStatus();
  for (Child& child : children_) {
    if (child.pid <= 0) continue;
    int status = 0;
    while (::waitpid(child.pid, &status, WNOHANG) != child.pid) {
      if (absl::Now() > deadline) {
        ::kill(child.pid, SIGKILL);
        ::waitpid(child.pid, &status, 0);
        result = absl::DeadlineExceededError(absl::StrCat(child.service.binary, " had to be killed"));
        break;
      }
      absl::SleepFor(absl::Milliseconds(20));
    }
    if (result.ok() && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
      result = absl::InternalError(absl::StrCat(child.service.binary, " stopped with status ", status));
    }
    child.pid = -1;
  }
  return result;
}

absl::Status PrintStatus(const StackConfig& config) {
  bool all_serving = true;
  for (const StackService& service : config.services) {
    const std::string health = CheckHealth(service.listen, absl::Seconds(2));
    all_serving &= health == "SERVING";
    std::cout << std::left << std::setw(16) << service.name << std::setw(22) << service.listen
              << health << "\n";
  }
  if (all_serving) return absl::OkStatus();
  return absl::UnavailableError("not every service is SERVING");
}

}  // namespace semnav::launcher
