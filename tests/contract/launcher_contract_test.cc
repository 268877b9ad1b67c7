// `semnav up` brings the five real services to SERVING, `semnav status` sees them, SIGTERM
// stops them all cleanly; a killed service comes back while the others keep running, a second
// stack on the same ports refuses to start, and no child outlives the launcher.
#include <arpa/inet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "services/launcher/free_port.h"
#include "services/launcher/stack_config.h"
#include "services/launcher/stack_state.h"
#include "tests/support/service_process.h"

namespace semnav::testing {
namespace {

using semnav::launcher::StackState;
using ::testing::HasSubstr;

std::string WriteStack() {
  const auto path =
      std::filesystem::temp_directory_path() / absl::StrCat("semnav_stack_", ::getpid(), ".yaml");
  std::ofstream out(path);
  out << "services:\n";
  for (const char* name : {"gateway", "mapping", "planning", "relocalization", "model-proxy"}) {
    out << "  " << name << ": {binary: semnav-" << name
        << ", listen: '127.0.0.1:" << *semnav::launcher::FreeLoopbackPort() << "'}\n";
  }
  return path.string();
}

TEST(LauncherTest, UpBringsAllFiveToServingQuicklyAndStopsThemOnSigterm) {
  const std::string stack = WriteStack();
  int out[2];
  ASSERT_EQ(::pipe(out), 0);
  const absl::Time started = absl::Now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(out[1], STDOUT_FILENO);
    const std::string path = BinaryPath("semnav");
    ::execl(path.c_str(), path.c_str(), "up", "--config", stack.c_str(), nullptr);
    ::_exit(127);
  }
  ::close(out[1]);
  std::string printed;
  char buffer[1024];
  while (printed.find("Ctrl-C") == std::string::npos) {
    const ssize_t n = ::read(out[0], buffer, sizeof(buffer));
    if (n <= 0) break;
    printed.append(buffer, static_cast<std::size_t>(n));
  }
  EXPECT_LT(absl::Now() - started, absl::Seconds(20));
  ASSERT_THAT(printed, HasSubstr("semnav stack is up"));
  for (const char* name : {"gateway", "mapping", "planning", "relocalization", "model-proxy"}) {
    EXPECT_THAT(printed, HasSubstr(name));
  }

  absl::StatusOr<ProcessResult> status = RunToCompletion("semnav", {"status", "--config", stack});
  ASSERT_TRUE(status.ok()) << status.status();
  EXPECT_EQ(status->exit_code, 0) << status->output;
  EXPECT_EQ(std::count(status->output.begin(), status->output.end(), '\n'), 5);

  ::kill(pid, SIGTERM);
  int code = 0;
  ::waitpid(pid, &code, 0);
  EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 0);
  while (true) {
    const ssize_t n = ::read(out[0], buffer, sizeof(buffer));
    if (n <= 0) break;
    printed.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(out[0]);
  EXPECT_THAT(printed, HasSubstr("semnav stack stopped."));

  // Nothing is left serving.
  absl::StatusOr<ProcessResult> after = RunToCompletion("semnav", {"status", "--config", stack});
  ASSERT_TRUE(after.ok());
  EXPECT_EQ(after->exit_code, 1);
}

// A running `semnav up --config stack`: its pid and what it printed up to "Ctrl-C".
struct RunningStack {
  pid_t pid = -1;
  int output_fd = -1;
  std::string printed;
};

RunningStack StartUp(const std::string& stack, const char* path_env = nullptr,
                     bool sim_robot = false) {
  RunningStack running;
  int out[2];
  if (::pipe(out) != 0) return running;
  running.pid = ::fork();
  if (running.pid == 0) {
    ::dup2(out[1], STDOUT_FILENO);
    const std::string path = BinaryPath("semnav");
    if (path_env != nullptr) ::setenv("PATH", path_env, 1);
    if (sim_robot) {
      ::execl(path.c_str(), path.c_str(), "up", "--sim-robot", "--config", stack.c_str(), nullptr);
    }
    ::execl(path.c_str(), path.c_str(), "up", "--config", stack.c_str(), nullptr);
    ::_exit(127);
  }
  ::close(out[1]);
  running.output_fd = out[0];
  char buffer[1024];
  while (running.printed.find("Ctrl-C") == std::string::npos) {
    const ssize_t n = ::read(out[0], buffer, sizeof(buffer));
    if (n <= 0) break;
    running.printed.append(buffer, static_cast<std::size_t>(n));
  }
  return running;
}

int StopUp(RunningStack& running, int signal_number = SIGTERM) {
  ::kill(running.pid, signal_number);
  int code = 0;
  ::waitpid(running.pid, &code, 0);
  ::close(running.output_fd);
  return code;
}

// The state letter of /proc/<pid>/stat ('R', 'S', 'T' stopped, 'Z' zombie), or 0 if it is gone.
char ProcessState(pid_t pid) {
  if (pid <= 0 || ::kill(pid, 0) != 0) return 0;
  std::ifstream stat(absl::StrCat("/proc/", pid, "/stat"));
  std::string line;
  std::getline(stat, line);
  const size_t paren = line.rfind(')');
  return paren != std::string::npos && paren + 2 < line.size() ? line[paren + 2] : 0;
}

// Running, sleeping or stopped; a zombie (exited, not yet reaped by whoever adopted it) counts
// as gone.
bool Alive(pid_t pid) {
  const char state = ProcessState(pid);
  return state != 0 && state != 'Z';
}

StackState LiveState(const std::string& stack) {
  absl::StatusOr<semnav::launcher::StackConfig> config = semnav::launcher::LoadStackConfig(stack);
  if (!config.ok()) return {};
  absl::StatusOr<StackState> state =
      semnav::launcher::ReadLiveStackState(semnav::launcher::StackStatePath(*config));
  return state.ok() ? *state : StackState{};
}

TEST(LauncherTest, KilledServiceIsRestartedAndTheOthersKeepRunning) {
  const std::string stack = WriteStack();
  RunningStack running = StartUp(stack);
  ASSERT_THAT(running.printed, HasSubstr("semnav stack is up"));
  const StackState before = LiveState(stack);
  ASSERT_EQ(before.children.size(), 5u);
  const pid_t mapping = before.children.at("mapping").pid;
  ASSERT_TRUE(Alive(mapping));
  ::kill(mapping, SIGKILL);

  // Back-off 0.5 s, then the new mapping must reach SERVING.
  absl::StatusOr<ProcessResult> status;
  const absl::Time deadline = absl::Now() + absl::Seconds(20);
  do {
    absl::SleepFor(absl::Milliseconds(200));
    status = RunToCompletion("semnav", {"status", "--config", stack});
    ASSERT_TRUE(status.ok()) << status.status();
  } while (status->exit_code != 0 && absl::Now() < deadline);
  EXPECT_EQ(status->exit_code, 0) << status->output;
  EXPECT_THAT(status->output, HasSubstr("restarts 1 (last: killed by signal 9"));

  const StackState after = LiveState(stack);
  EXPECT_EQ(after.children.at("mapping").restarts, 1);
  EXPECT_NE(after.children.at("mapping").pid, mapping);
  for (const char* name : {"gateway", "planning", "relocalization", "model-proxy"}) {
    EXPECT_EQ(after.children.at(name).pid, before.children.at(name).pid) << name;
    EXPECT_EQ(after.children.at(name).restarts, 0) << name;
  }
  const int code = StopUp(running);
  EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 0);
}

// Regression (web_stack_e2e, once in a few runs): SIGTERM reached the robot and the gateway
// together; the robot saw its session closed first, exited 1, and `semnav up` reported an
// unclean stop. Clients now stop before the services: while the robot is frozen (SIGSTOP), the
// gateway is not signalled; once it runs again, everything stops cleanly.
TEST(LauncherTest, TheSimRobotStopsBeforeTheServicesItTalksTo) {
  const std::string stack = WriteStack();
  RunningStack running = StartUp(stack, nullptr, /*sim_robot=*/true);
  ASSERT_THAT(running.printed, HasSubstr("semnav stack is up"));
  const StackState state = LiveState(stack);
  ASSERT_TRUE(state.children.contains("sim-robot"));
  const pid_t robot = state.children.at("sim-robot").pid;
  const pid_t gateway = state.children.at("gateway").pid;
  ASSERT_TRUE(Alive(robot));
  ::kill(robot, SIGSTOP);
  // SIGSTOP takes effect when the robot next enters the kernel. A SIGTERM that arrives before
  // then is taken first (lower number), and the robot stops itself before it freezes.
  const absl::Time frozen_by = absl::Now() + absl::Seconds(10);
  while (ProcessState(robot) != 'T' && absl::Now() < frozen_by) {
    absl::SleepFor(absl::Milliseconds(10));
  }
  ASSERT_EQ(ProcessState(robot), 'T');
  ::kill(running.pid, SIGTERM);
  absl::SleepFor(absl::Seconds(1.5));
  const bool gateway_alive_while_robot_frozen = Alive(gateway);
  ::kill(robot, SIGCONT);
  int code = 0;
  ::waitpid(running.pid, &code, 0);
  char buffer[1024];
  for (ssize_t n; (n = ::read(running.output_fd, buffer, sizeof(buffer))) > 0;) {
    running.printed.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(running.output_fd);
  EXPECT_TRUE(gateway_alive_while_robot_frozen)
      << "the gateway was stopped while its robot still ran; the launcher said:\n"
      << running.printed;
  EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 0) << code << "\n" << running.printed;
  EXPECT_FALSE(Alive(gateway));
}

TEST(LauncherTest, SecondStackOnTheSamePortsRefusesToStart) {
  const std::string stack = WriteStack();
  RunningStack running = StartUp(stack);
  ASSERT_THAT(running.printed, HasSubstr("semnav stack is up"));

  absl::StatusOr<ProcessResult> same = RunToCompletion("semnav", {"up", "--config", stack});
  ASSERT_TRUE(same.ok());
  EXPECT_EQ(same->exit_code, 1);
  EXPECT_THAT(same->output, HasSubstr("already runs this stack"));

  // Another stack file that reuses one port: refused by the port check, naming the service.
  absl::StatusOr<semnav::launcher::StackConfig> config = semnav::launcher::LoadStackConfig(stack);
  ASSERT_TRUE(config.ok());
  const auto other = std::filesystem::temp_directory_path() /
                     absl::StrCat("semnav_stack_other_", ::getpid(), ".yaml");
  std::ofstream(other) << "services:\n  planning: {binary: semnav-planning, listen: '"
                       << config->AddressOf("planning") << "'}\n";
  absl::StatusOr<ProcessResult> overlap =
      RunToCompletion("semnav", {"up", "--config", other.string()});
  ASSERT_TRUE(overlap.ok());
  EXPECT_EQ(overlap->exit_code, 1);
  EXPECT_THAT(overlap->output,
              HasSubstr("planning: " + config->AddressOf("planning") + " is already in use"));

  // A service binary started by hand on a taken port fails instead of sharing it.
  absl::StatusOr<ProcessResult> twin = RunToCompletion(
      "semnav-planning", {"--listen", config->AddressOf("planning")}, absl::Seconds(10));
  ASSERT_TRUE(twin.ok());
  EXPECT_NE(twin->exit_code, 0);
  EXPECT_THAT(twin->output, HasSubstr("cannot bind"));

  const int code = StopUp(running);
  EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 0);
}

TEST(LauncherTest, NoServiceOutlivesAKilledLauncher) {
  const std::string stack = WriteStack();
  RunningStack running = StartUp(stack);
  ASSERT_THAT(running.printed, HasSubstr("semnav stack is up"));
  const StackState state = LiveState(stack);
  ASSERT_EQ(state.children.size(), 5u);
  StopUp(running, SIGKILL);
  const absl::Time deadline = absl::Now() + absl::Seconds(15);
  for (const auto& [name, child] : state.children) {
    while (Alive(child.pid) && absl::Now() < deadline) absl::SleepFor(absl::Milliseconds(50));
    EXPECT_FALSE(Alive(child.pid)) << name << " outlived its launcher";
  }
}

TEST(LauncherTest, WithoutNodeTheStackStartsAndSaysWhyThereIsNoDashboard) {
  const std::string stack = WriteStack();
  std::ofstream(stack, std::ios::app)
      << "dashboard: {listen: '127.0.0.1:" << *semnav::launcher::FreeLoopbackPort() << "'}\n";
  RunningStack running = StartUp(stack, "/nonexistent");
  EXPECT_THAT(running.printed, HasSubstr("semnav stack is up"));
  EXPECT_THAT(running.printed,
              HasSubstr("dashboard: not started: Node.js (`node`) is not on PATH"));
  EXPECT_THAT(running.printed, ::testing::Not(HasSubstr("dashboard: http")));
  const int code = StopUp(running);
  EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 0);
}

TEST(LauncherTest, DashboardIsServedAndItsUrlPrinted) {
  const std::string stack = WriteStack();
  const int port = *semnav::launcher::FreeLoopbackPort();
  std::ofstream(stack, std::ios::app) << "dashboard: {listen: '127.0.0.1:" << port << "'}\n";
  RunningStack running = StartUp(stack);
  EXPECT_THAT(running.printed, HasSubstr(absl::StrCat("dashboard: http://127.0.0.1:", port, "/")));
  absl::StatusOr<ProcessResult> status = RunToCompletion("semnav", {"status", "--config", stack});
  ASSERT_TRUE(status.ok());
  EXPECT_THAT(status->output, HasSubstr(absl::StrCat("SERVING http://127.0.0.1:", port, "/")));
  const int code = StopUp(running);
  EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 0);
}

TEST(LauncherTest, ATakenDashboardPortCostsTheDashboardNotTheStack) {
  const std::string stack = WriteStack();
  const int port = *semnav::launcher::FreeLoopbackPort();
  const int blocker = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  ASSERT_EQ(::bind(blocker, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  ASSERT_EQ(::listen(blocker, 1), 0);
  std::ofstream(stack, std::ios::app) << "dashboard: {listen: '127.0.0.1:" << port << "'}\n";
  RunningStack running = StartUp(stack);
  EXPECT_THAT(running.printed, HasSubstr("semnav stack is up"));
  EXPECT_THAT(running.printed, HasSubstr(absl::StrCat("dashboard: not started: 127.0.0.1:", port,
                                                      " is already in use")));
  const int code = StopUp(running);
  EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 0);
  ::close(blocker);
}

TEST(LauncherTest, UnknownBenchAreaListsTheBuiltOnes) {
  absl::StatusOr<ProcessResult> result = RunToCompletion("semnav", {"bench", "nonsense"});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result->exit_code, 2);
  EXPECT_THAT(result->output, HasSubstr("no benchmark for area 'nonsense'"));
}

TEST(LauncherTest, BadStackConfigIsNamed) {
  const auto path = std::filesystem::temp_directory_path() / "semnav_bad_stack.yaml";
  std::ofstream(path) << "services: {mapping: {binary: semnav-mapping}}\n";
  absl::StatusOr<ProcessResult> result =
      RunToCompletion("semnav", {"up", "--config", path.string()});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result->exit_code, 2);
  EXPECT_THAT(result->output, HasSubstr("services.mapping.listen: is required"));
}

}  // namespace
}  // namespace semnav::testing
