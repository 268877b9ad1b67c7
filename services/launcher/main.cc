// semnav: runs the whole stack on one machine and hosts the benchmark and demo entry points.
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <set>

#include "absl/strings/str_cat.h"
#include "services/common/cli/executable_dir.h"
#include "services/common/cli/flags.h"
#include "services/common/cli/help.h"
#include "services/launcher/health_probe.h"
#include "services/launcher/stack_runner.h"

namespace {

using semnav::launcher::StackConfig;

constexpr char kUsage[] = R"(Usage: semnav <command> [flags]

Commands:
  up [--config FILE] [--sim-robot]
                            start every service on localhost, wait until all are SERVING,
                            then the browser dashboard; print the endpoints and the dashboard
                            URL; restart a service that dies (with back-off); stop them all on
                            Ctrl-C / SIGTERM. --sim-robot adds a simulated robot in a generated
                            home that carries out instructions typed in the dashboard or given
                            to semnavctl
  status [--config FILE]    health of every service of the stack and the restarts `semnav up`
                            made (exit 1 if any is down)
  probe --addr HOST:PORT    health of one service, with TLS/mTLS and token flags (see
                            `semnav probe --help`); exit 0 when SERVING: for container and
                            orchestrator health checks
  bench <area> [args...]    run the benchmark of an area (e.g. mapping, planning,
                            relocalization, modelproxy, gateway, mission); `--json FILE` writes
                            its figures
  demo [args...]            start the stack, run one simulated search mission (a target out of
                            sight in a generated home), print its progress, the result and where
                            the report is (`semnav demo --help`)
  help                      this text

Without --config the embedded localhost stack (same as deploy/local.yaml) is used: no model
keys, no network, the offline reasoner.
)";

struct StackCommand {
  StackConfig stack;
  semnav::launcher::RunnerOptions options;
};

absl::StatusOr<StackCommand> StackFromFlags(const std::string& command, int argc, char** argv) {
  std::vector<semnav::FlagSpec> specs = {{"config", "FILE", "stack YAML"}};
  if (command == "up")
    specs.push_back({"sim-robot", "", "also run a simulated robot in a generated home"});
  absl::StatusOr<semnav::ParsedFlags> flags = semnav::ParseFlags(argc, argv, 2, specs);
  if (!flags.ok()) return flags.status();
  if (!flags->positional.empty()) {
    return absl::InvalidArgumentError("unexpected argument '" + flags->positional[0] + "'");
  }
  StackCommand result;
  result.options.sim_robot = flags->Has("sim-robot");
  if (auto path = flags->Get("config")) {
    absl::StatusOr<StackConfig> loaded = semnav::launcher::LoadStackConfig(*path);
    if (!loaded.ok()) return loaded.status();
    result.stack = *std::move(loaded);
  } else {
    result.stack = semnav::launcher::DefaultStackConfig();
  }
  return result;
}

int Up(const StackConfig& stack, const semnav::launcher::RunnerOptions& options) {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGCHLD);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  semnav::launcher::StackRunner runner(stack, semnav::ExecutableDir(), options);
  if (absl::Status started = runner.Start(); !started.ok()) {
    std::cerr << "semnav up: " << started.message() << "\n";
    (void)runner.Stop();
    return 1;
  }
  std::cout << "semnav stack is up:\n";
  for (const auto& service : stack.services) {
    std::cout << "  " << service.name
              << std::string(16 - std::min<std::size_t>(15, service.name.size()), ' ')
              << service.listen << "\n";
  }
  if (options.sim_robot) {
    std::cout << "  sim-robot       robot id '" << stack.sim_robot.robot_id
              << "' in a generated home (seed " << stack.sim_robot.world_seed << ")\n";
  }
  for (const std::string& note : runner.notes()) std::cout << note << "\n";
  if (runner.dashboard_url()) std::cout << "dashboard: " << *runner.dashboard_url() << "\n";
  std::cout << "Ctrl-C stops every service." << std::endl;
  (void)runner.Supervise();
  absl::Status stopped = runner.Stop();
  if (!stopped.ok()) {
    std::cerr << "semnav up: " << stopped.message() << "\n";
    return 1;
  }
  std::cout << "semnav stack stopped." << std::endl;
  return 0;
}

// Replaces this process by a sibling binary, passing argv[first..].
int ExecSibling(const std::string& binary, int argc, char** argv, int first) {
  const std::string path = absl::StrCat(semnav::ExecutableDir(), "/", binary);
  std::vector<char*> args = {const_cast<char*>(path.c_str())};
  for (int i = first; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  ::execv(path.c_str(), args.data());
  std::cerr << "semnav: cannot run " << path << "\n";
  return 1;
}

int Bench(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "semnav bench: name an area\n";
    return 2;
  }
  const std::string area = argv[2];
  const std::string binary = "semnav-bench-" + area;
  if (::access(absl::StrCat(semnav::ExecutableDir(), "/", binary).c_str(), X_OK) != 0) {
    std::set<std::string> areas;
    for (const auto& entry : std::filesystem::directory_iterator(semnav::ExecutableDir())) {
      const std::string name = entry.path().filename().string();
      if (name.starts_with("semnav-bench-")) areas.insert(name.substr(13));
    }
    std::cerr << "semnav bench: no benchmark for area '" << area << "'; built areas:";
    for (const std::string& a : areas) std::cerr << " " << a;
    std::cerr << "\n";
    return 2;
  }
  return ExecSibling(binary, argc, argv, 3);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string command = argc > 1 ? argv[1] : "help";
  if (command == "help" || command == "--help" || command == "-h") {
    std::cout << kUsage;
    return 0;
  }
  if (command == "bench") return Bench(argc, argv);
  if (command == "probe") {
    if (argc > 2 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h")) {
      std::cout << "Usage: semnav probe --addr HOST:PORT [flags]\n\nFlags:\n"
                << semnav::FlagsHelp(semnav::launcher::ProbeFlags());
      return 0;
    }
    return semnav::launcher::RunProbe(argc, argv, 2);
  }
  if (command == "demo") return ExecSibling("semnav-sim-demo", argc, argv, 2);
  if (command == "up" || command == "status") {
    if (semnav::HelpRequested(argc, argv)) {
      std::cout << kUsage;
      return 0;
    }
    absl::StatusOr<StackCommand> parsed = StackFromFlags(command, argc, argv);
    if (!parsed.ok()) {
      std::cerr << "semnav " << command << ": " << parsed.status().message() << "\n" << kUsage;
      return 2;
    }
    if (command == "up") return Up(parsed->stack, parsed->options);
    absl::Status status = semnav::launcher::PrintStatus(parsed->stack);
    return status.ok() ? 0 : 1;
  }
  std::cerr << "semnav: unknown command '" << command << "'\n" << kUsage;
  return 2;
}
