// `semnav up` brings the five real services to SERVING, `semnav status` sees them, SIGTERM
// stops them all cleanly.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "services/launcher/free_port.h"
#include "tests/support/service_process.h"

namespace semnav::testing {
namespace {

using ::testing::HasSubstr;

std::string WriteStack() {
  const auto path = std::filesystem::temp_directory_path() /
                    absl::StrCat("semnav_stack_", ::getpid(), ".yaml");
  std::ofstream out(path);
  out << "services:\n";
  for (const char* name : {"gateway", "mapping", "planning", "relocalization", "model-proxy"}) {
    out << "  " << name << ": {binary: semnav-" << name << ", listen: '127.0.0.1:" << *semnav::launcher::FreeLoopbackPort()
        << "'}\n";
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

TEST(LauncherTest, UnknownBenchAreaListsTheBuiltOnes) {
  absl::StatusOr<ProcessResult> result = RunToCompletion("semnav", {"bench", "nonsense"});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result->exit_code, 2);
  EXPECT_THAT(result->output, HasSubstr("no benchmark for area 'nonsense'"));
}

TEST(LauncherTest, BadStackConfigIsNamed) {
  const auto path = std::filesystem::temp_directory_path() / "semnav_bad_stack.yaml";
  std::ofstream(path) << "services: {mapping: {binary: semnav-mapping}}\n";
  absl::StatusOr<ProcessResult> result = RunToCompletion("semnav", {"up", "--config", path.string()});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result->exit_code, 2);
  EXPECT_THAT(result->output, HasSubstr("services.mapping.listen: is required"));
}

}  // namespace
}  // namespace semnav::testing
