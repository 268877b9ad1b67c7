#include "services/launcher/stack_config.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <memory>

#include "absl/strings/str_cat.h"
#include "services/common/config/config_reader.h"
#include "services/launcher/default_stack.h"

namespace semnav::launcher {
namespace {

// A fresh folder for one parse's inline settings, so two stacks read by one process never
// share files; removed with the last copy of the config that holds it.
std::shared_ptr<const std::filesystem::path> NewSettingsFolder() {
  static std::atomic<int> parses{0};
  return std::shared_ptr<const std::filesystem::path>(
      new std::filesystem::path(std::filesystem::temp_directory_path() /
                                absl::StrCat("semnav-stack-", ::getpid(), "-", parses++)),
      [](const std::filesystem::path* dir) {
        std::error_code ignored;
        std::filesystem::remove_all(*dir, ignored);
        delete dir;
      });
}

// Writes a service's inline settings where its binary can read them as a config file.
absl::StatusOr<std::string> WriteSettings(const std::filesystem::path& dir, const std::string& name,
                                          const std::string& yaml) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  const std::filesystem::path path = dir / (name + ".yaml");
  std::ofstream out(path);
  out << yaml << "\n";
  if (error || !out) {
    return absl::InternalError(
        absl::StrCat("services.", name, ".settings: cannot write ", path.string()));
  }
  return path.string();
}

absl::StatusOr<StackConfig> ParseStack(ConfigReader& root, const std::filesystem::path& base) {
  StackConfig stack;
  root.Read("startup_timeout_s", &stack.startup_timeout_s)
      .Read("stop_timeout_s", &stack.stop_timeout_s);
  root.Check(stack.startup_timeout_s > 0, "startup_timeout_s", "must be > 0");
  root.Check(stack.stop_timeout_s > 0, "stop_timeout_s", "must be > 0");
  ConfigReader restart = root.Child("restart");
  restart.Read("initial_backoff_s", &stack.restart.initial_backoff_s)
      .Read("max_backoff_s", &stack.restart.max_backoff_s)
      .Read("stable_after_s", &stack.restart.stable_after_s);
  restart.Check(stack.restart.initial_backoff_s > 0, "initial_backoff_s", "must be > 0");
  restart.Check(stack.restart.max_backoff_s >= stack.restart.initial_backoff_s, "max_backoff_s",
                "must be >= initial_backoff_s");
  restart.Check(stack.restart.stable_after_s > 0, "stable_after_s", "must be > 0");
  if (root.Has("dashboard")) {
    ConfigReader dashboard = root.Child("dashboard");
    stack.dashboard.enabled = true;
    dashboard.Read("enabled", &stack.dashboard.enabled)
        .Read("listen", &stack.dashboard.listen)
        .Read("robot_id", &stack.dashboard.robot_id);
    dashboard.Check(!stack.dashboard.listen.empty(), "listen", "is required (host:port)");
  }
  ConfigReader sim_robot = root.Child("sim_robot");
  sim_robot.Read("robot_id", &stack.sim_robot.robot_id)
      .Read("world_seed", &stack.sim_robot.world_seed)
      .Read("speed", &stack.sim_robot.speed);
  sim_robot.Check(!stack.sim_robot.robot_id.empty(), "robot_id", "must not be empty");
  sim_robot.Check(stack.sim_robot.world_seed >= 0, "world_seed", "must be >= 0");
  sim_robot.Check(stack.sim_robot.speed > 0 && stack.sim_robot.speed <= 100, "speed",
                  "must be in (0, 100]");
  ConfigReader services = root.Child("services");
  for (const std::string& name : services.Keys()) {
    ConfigReader entry = services.Child(name);
    StackService service{.name = name, .binary = "", .listen = "", .config = ""};
    std::string settings;
    entry.Read("binary", &service.binary)
        .Read("listen", &service.listen)
        .Read("config", &service.config);
    entry.ReadSubtree("settings", &settings);
    entry.Check(service.config.empty() || settings.empty(), "settings",
                "give a config file or inline settings, not both");
    entry.Check(!service.binary.empty(), "binary", "is required");
    entry.Check(!service.listen.empty(), "listen", "is required (host:port)");
    if (!service.config.empty() && std::filesystem::path(service.config).is_relative()) {
      service.config = (base / service.config).lexically_normal().string();
    }
    if (!settings.empty() && service.config.empty()) {
      if (stack.settings_folder == nullptr) stack.settings_folder = NewSettingsFolder();
      absl::StatusOr<std::string> path = WriteSettings(*stack.settings_folder, name, settings);
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

std::string StackConfig::AddressOf(const std::string& name) const {
  for (const StackService& service : services) {
    if (service.name == name) return service.listen;
  }
  return "";
}

std::optional<StackConfig::ClientEndpoints> StackConfig::ClientEndpointsOf() const {
  ClientEndpoints endpoints{AddressOf("gateway"), AddressOf("mapping"), AddressOf("planning")};
  if (endpoints.gateway.empty() || endpoints.mapping.empty() || endpoints.planning.empty())
    return std::nullopt;
  return endpoints;
}

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
