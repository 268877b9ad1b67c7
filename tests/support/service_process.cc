#include "tests/support/service_process.h"

#include <fcntl.h>
#include <grpcpp/create_channel.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "grpc/health/v1/health.grpc.pb.h"

namespace semnav::testing {
namespace {

// In the child before exec: a test that crashes or is killed by ctest's timeout takes its
// services with it (no orphans); PR_SET_PDEATHSIG alone misses a parent that died before it.
void DieWithParent(pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) ::_exit(127);
}

std::vector<char*> Argv(const std::string& path, const std::vector<std::string>& args) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(path.c_str()));
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  return argv;
}

enum class ReadEnd { kStopped, kEndOfFile, kTimedOut };

// Appends what arrives on fd to out until `stop(out)`, end of file, or the deadline.
template <typename Stop>
ReadEnd ReadUntil(int fd, std::string& out, absl::Time deadline, Stop stop) {
  char buffer[4096];
  while (!stop(out)) {
    const int64_t wait_ms = absl::ToInt64Milliseconds(deadline - absl::Now());
    if (wait_ms <= 0) return ReadEnd::kTimedOut;
    pollfd pfd{fd, POLLIN, 0};
    if (::poll(&pfd, 1, static_cast<int>(std::min<int64_t>(wait_ms, 200))) <= 0) continue;
    const ssize_t n = ::read(fd, buffer, sizeof(buffer));
    if (n <= 0) return ReadEnd::kEndOfFile;
    out.append(buffer, static_cast<std::size_t>(n));
  }
  return ReadEnd::kStopped;
}

}  // namespace

std::string BinaryPath(const std::string& binary) {
  return absl::StrCat(SEMNAV_BIN_DIR, "/", binary);
}

absl::Status WaitForServing(const std::shared_ptr<grpc::Channel>& channel,
                            const std::string& service, absl::Duration timeout) {
  auto stub = grpc::health::v1::Health::NewStub(channel);
  const absl::Time deadline = absl::Now() + timeout;
  std::string last = "no answer";
  while (absl::Now() < deadline) {
    grpc::ClientContext context;
    context.set_deadline(absl::ToChronoTime(absl::Now() + absl::Seconds(1)));
    grpc::health::v1::HealthCheckRequest request;
    request.set_service(service);
    grpc::health::v1::HealthCheckResponse response;
    grpc::Status status = stub->Check(&context, request, &response);
    if (status.ok() && response.status() == grpc::health::v1::HealthCheckResponse::SERVING) {
      return absl::OkStatus();
    }
    last = status.ok() ? "NOT_SERVING" : status.error_message();
    absl::SleepFor(absl::Milliseconds(50));
  }
  return absl::DeadlineExceededError(absl::StrCat("health of '", service, "' not SERVING: ", last));
}

absl::StatusOr<std::unique_ptr<ServiceProcess>> ServiceProcess::Start(
    const std::string& binary, std::vector<std::string> extra_args, absl::Duration timeout,
    bool wait_for_health) {
  if (std::find(extra_args.begin(), extra_args.end(), "--listen") == extra_args.end()) {
    extra_args.push_back("--listen");
    extra_args.push_back("127.0.0.1:0");
  }
  const std::string path = BinaryPath(binary);
  if (::access(path.c_str(), X_OK) != 0)
    return absl::NotFoundError(absl::StrCat(path, " not built"));
  int out[2];
  if (::pipe2(out, O_CLOEXEC) != 0) return absl::InternalError("pipe failed");
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) return absl::InternalError("fork failed");
  if (pid == 0) {
    DieWithParent(parent);
    ::dup2(out[1], STDOUT_FILENO);
    std::vector<char*> argv = Argv(path, extra_args);
    ::execv(path.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(out[1]);
  std::string printed;
  const std::string marker = " serving on ";
  const bool announced =
      ReadUntil(out[0], printed, absl::Now() + timeout, [&](const std::string& s) {
        const auto at = s.find(marker);
        return at != std::string::npos && s.find('\n', at) != std::string::npos;
      }) == ReadEnd::kStopped;
  // Keep draining stdout in the background so the child never blocks on a full pipe.
  std::thread([fd = out[0]] {
    char sink[4096];
    while (::read(fd, sink, sizeof(sink)) > 0) {
    }
    ::close(fd);
  }).detach();
  std::unique_ptr<ServiceProcess> process(new ServiceProcess(pid, ""));
  if (!announced) {
    return absl::DeadlineExceededError(absl::StrCat(binary, " did not start: ", printed));
  }
  const auto at = printed.find(marker) + marker.size();
  process->address_ = printed.substr(at, printed.find('\n', at) - at);
  if (!wait_for_health) return process;
  absl::Status serving = WaitForServing(process->channel(), "", timeout);
  if (!serving.ok()) return serving;
  return process;
}

std::shared_ptr<grpc::Channel> ServiceProcess::channel() const {
  return grpc::CreateChannel(address_, grpc::InsecureChannelCredentials());
}

absl::StatusOr<int> ServiceProcess::Terminate(absl::Duration timeout) {
  if (reaped_) return absl::FailedPreconditionError("already terminated");
  ::kill(pid_, SIGTERM);
  const absl::Time deadline = absl::Now() + timeout;
  int status = 0;
  while (absl::Now() < deadline) {
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      reaped_ = true;
      if (WIFEXITED(status)) return WEXITSTATUS(status);
      return absl::InternalError(absl::StrCat("died from signal ", WTERMSIG(status)));
    }
    absl::SleepFor(absl::Milliseconds(20));
  }
  ::kill(pid_, SIGKILL);
  ::waitpid(pid_, &status, 0);
  reaped_ = true;
  return absl::DeadlineExceededError("did not exit after SIGTERM; killed");
}

ServiceProcess::~ServiceProcess() {
  if (!reaped_) (void)Terminate(absl::Seconds(10));
}

absl::StatusOr<ProcessResult> RunToCompletion(const std::string& binary,
                                              const std::vector<std::string>& args,
                                              absl::Duration timeout) {
  const std::string path = BinaryPath(binary);
  int out[2];
  if (::pipe2(out, O_CLOEXEC) != 0) return absl::InternalError("pipe failed");
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) return absl::InternalError("fork failed");
  if (pid == 0) {
    DieWithParent(parent);
    ::dup2(out[1], STDOUT_FILENO);
    ::dup2(out[1], STDERR_FILENO);
    std::vector<char*> argv = Argv(path, args);
    ::execv(path.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(out[1]);
  ProcessResult result;
  const bool eof = ReadUntil(out[0], result.output, absl::Now() + timeout,
                             [](const std::string&) { return false; }) == ReadEnd::kEndOfFile;
  ::close(out[0]);
  int status = 0;
  const absl::Time deadline = absl::Now() + (eof ? absl::Seconds(5) : absl::ZeroDuration());
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (absl::Now() >= deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return absl::DeadlineExceededError(absl::StrCat(binary, " did not finish"));
    }
    absl::SleepFor(absl::Milliseconds(10));
  }
  if (result.exit_code == -1 && WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  return result;
}

}  // namespace semnav::testing
