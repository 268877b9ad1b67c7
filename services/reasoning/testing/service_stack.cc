#include "services/reasoning/testing/service_stack.h"

#include <filesystem>
#include <fstream>

#include "gtest/gtest.h"

namespace semnav::reasoning::testing {

std::string FreshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> StartWithConfig(
    const std::string& binary, const std::string& dir, const std::string& file,
    const std::string& yaml) {
  const std::string path = dir + "/" + file;
  std::ofstream(path) << yaml;
  return semnav::testing::ServiceProcess::Start(binary, {"--config", path});
}

absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> StartMapping(
    const std::string& dir) {
  return StartWithConfig(
      "semnav-mapping", dir, "mapping.yaml",
      "mapping:\n  store_directory: " + dir + "/maps\n  watch_min_interval_ms: 20\n");
}

}  // namespace semnav::reasoning::testing
