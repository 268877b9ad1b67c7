#pragma once

#include <grpcpp/channel.h>
#include <sys/types.h>

#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"

namespace semnav::testing {

// A real semnav binary started on a free loopback port for contract tests. Start() returns once
// the binary printed its "serving on" line and grpc.health.v1 reports SERVING.
class ServiceProcess {
 public:
  // `binary` is a file name in SEMNAV_BIN_DIR, e.g. "semnav-mapping". `--listen
  // 127.0.0.1:0` is appended unless extra_args already holds --listen.
  // With wait_for_health false it returns once the "serving on" line is printed (for servers
  // that need TLS or a token, which the plaintext probe cannot pass).
  static absl::StatusOr<std::unique_ptr<ServiceProcess>> Start(
      const std::string& binary, std::vector<std::string> extra_args = {},
      absl::Duration timeout = absl::Seconds(20), bool wait_for_health = true);
  ~ServiceProcess();

  const std::string& address() const { return address_; }
  // A plaintext channel to address().
  std::shared_ptr<grpc::Channel> channel() const;
  pid_t pid() const { return pid_; }

  // Sends SIGTERM and waits up to `timeout`; returns the exit code, or an error if the process
  // had to be killed or died from a signal.
  absl::StatusOr<int> Terminate(absl::Duration timeout = absl::Seconds(10));

 private:
  ServiceProcess(pid_t pid, std::string address) : pid_(pid), address_(std::move(address)) {}
  pid_t pid_;
  std::string address_;
  bool reaped_ = false;
};

// Runs a binary to completion (e.g. `--help`, a bad config) and returns its exit code and
// combined stdout+stderr.
struct ProcessResult {
  int exit_code = -1;
  std::string output;
};
absl::StatusOr<ProcessResult> RunToCompletion(const std::string& binary,
                                              const std::vector<std::string>& args,
                                              absl::Duration timeout = absl::Seconds(20));

// Path of a binary in SEMNAV_BIN_DIR.
std::string BinaryPath(const std::string& binary);

// Waits until grpc.health.v1 on `channel` answers SERVING for `service` ("" = whole server).
absl::Status WaitForServing(const std::shared_ptr<grpc::Channel>& channel,
                            const std::string& service, absl::Duration timeout);

}  // namespace semnav::testing
