#include "services/launcher/stack_config.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include "absl/strings/str_cat.h"

#include "services/common/config/config_reader.h"
#include "services/launcher/default_stack.h"

namespace semnav::launcher {
namespace {

// Writes a service's inline settings where its binary can read them as a config file.
absl::StatusOr<std::string> WriteSettings(const std::string& name, const std::string& yaml) {
  // A fresh folder each time, so two stacks read by one process never share files.
  static std::atomic<int> parses{0};
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    absl::StrCat("semnav-stack-", ::getpid(), "-", parses++);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  const std::filesystem::path path = dir / (name + ".yaml");
  std::ofstream out(path);
  out << yaml << "\n";
  if (error || !out) {
    return absl::InternalError(absl::StrCat("services.", name, ".settings: cannot write ", path.string()));
  }
  return path.string();
}

absl::StatusOr<StackConfig> ParseStack(ConfigReader& root, const std::filesystem::path& base) {
  StackConfig stack;
  root.Read("startup_timeout_s", &stack.startup_timeout_s)
      .Read("stop_timeout_s", &stack.stop_timeout_s);
  root.Check(stack.startup_timeout_s > 0, "startup_timeout_s", "must be > 0");
  root.Check(stack.stop_timeout_s > 0, "stop_timeout_s", "must be > 0");
  ConfigReader services = root.Child("services");
  for (const std::string& name : services.Keys()) {
    ConfigReader entry = services.Child(name);
    StackService service{.name = name, .binary = "", .listen = "", .config = ""};
    std::string settings;
    entry.Read("binary", &service.binary).Read("listen", &service.listen).Read("config", &service.config);
    entry.ReadSubtree("settings", &settings);
    entry.Check(service.config.empty() || settings.empty(), "settings",
                "give a config file or inline settings, not both");
    entry.Check(!service.binary.empty(), "binary", "is required");
    entry.Check(!service.listen.empty(), "listen", "is required (host:port)");
    if (!service.config.empty() && std::filesystem::path(service.config).is_relative()) {
      service.config = (base / service.config).lexically_normal().string();
    }
    if (!settings.empty() && service.config.empty()) {
      absl::StatusOr<std::string> path = WriteSettings(name, settings);
      if (!path.ok()) return path.status();
      service.config = *path;
    }
    stack.services.push_back(service);
  }
  root.Check(!stack.services.empty(), "services", "must list at least one service");
  if (absl::Status status = root.Finish(); !status.ok()) return status;
  return stack;
}

}  // namespace

absl::StatusOr<StackConfig> LoadStackConfig(const std::string& path) {
  absl::StatusOr<ConfigReader> root = ConfigReader::FromFile(path);
  if (!root.ok()) return root.status();
  return ParseStack(*root, std::filesystem::absolute(path).parent_path());
}

StackConfig DefaultStackConfig() {
  absl::StatusOr<ConfigReader> root = ConfigReader::FromString(kDefaultStackYaml);
  absl::StatusOr<StackConfig> stack = ParseStack(*root, std::filesystem::current_path());
  return *stack;  // deploy/local.yaml, checked by StackConfigTest
}

}  // namespace semnav::launcher
