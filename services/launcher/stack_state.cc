#include "services/launcher/stack_state.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

#include "absl/strings/str_cat.h"
#include "services/common/storage/durable_file.h"

namespace semnav::launcher {
namespace {

std::string StackKey(const StackConfig& config) {
  std::string addresses;
  for (const StackService& service : config.services)
    absl::StrAppend(&addresses, service.listen, ";");
  return absl::StrCat(absl::Hex(std::hash<std::string>{}(addresses), absl::kZeroPad16));
}

}  // namespace

std::string StackStatePath(const StackConfig& config) {
  return (std::filesystem::temp_directory_path() /
          absl::StrCat("semnav-up-", StackKey(config), ".json"))
      .string();
}

std::string StackLockPath(const StackConfig& config) {
  return (std::filesystem::temp_directory_path() /
          absl::StrCat("semnav-up-", StackKey(config), ".lock"))
      .string();
}

absl::Status WriteStackState(const std::string& path, const StackState& state) {
  nlohmann::json json;
  json["launcher_pid"] = state.launcher_pid;
  json["dashboard_url"] = state.dashboard_url;
  for (const auto& [name, child] : state.children) {
    json["children"][name] = {
        {"pid", child.pid}, {"restarts", child.restarts}, {"last_exit", child.last_exit}};
  }
  return storage::WriteFileAtomically(path, json.dump() + "\n");
}

absl::StatusOr<StackState> ReadLiveStackState(const std::string& path) {
  absl::StatusOr<std::string> text = storage::ReadWholeFile(path);
  if (!text.ok()) return absl::NotFoundError(absl::StrCat(path, " not found"));
  const nlohmann::json json = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (!json.is_object()) return absl::NotFoundError(absl::StrCat(path, " is not a stack state"));
  StackState state;
  state.launcher_pid = json.value("launcher_pid", -1);
  state.dashboard_url = json.value("dashboard_url", "");
  if (state.launcher_pid <= 0 || (::kill(state.launcher_pid, 0) != 0 && errno == ESRCH)) {
    return absl::NotFoundError("the launcher that wrote the stack state is gone");
  }
  if (json.contains("children") && json["children"].is_object()) {
    for (const auto& [name, child] : json["children"].items()) {
      state.children[name] = {child.value("pid", -1), child.value("restarts", 0),
                              child.value("last_exit", "")};
    }
  }
  return state;
}

absl::StatusOr<StackLock> StackLock::Acquire(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return absl::InternalError(absl::StrCat("cannot open ", path));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char holder[32] = {};
    const ssize_t n = ::pread(fd, holder, sizeof(holder) - 1, 0);
    ::close(fd);
    return absl::FailedPreconditionError(absl::StrCat(
        "another `semnav up` (pid ", n > 0 ? std::string(holder, static_cast<size_t>(n)) : "?",
        ") already runs this stack"));
  }
  const std::string pid = std::to_string(::getpid());
  if (::ftruncate(fd, 0) != 0 ||
      ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    ::close(fd);
    return absl::InternalError(absl::StrCat("cannot write ", path));
  }
  return StackLock(fd);
}

StackLock::StackLock(StackLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }

StackLock::~StackLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace semnav::launcher
