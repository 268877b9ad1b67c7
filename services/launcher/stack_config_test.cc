#include "services/launcher/stack_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "services/common/config/config_reader.h"

namespace semnav::launcher {
namespace {

using ::testing::HasSubstr;

std::string ReadFile(const std::string& path) {
  if (path.empty()) return "";
  std::ifstream in(path);
  std::stringstream content;
  content << in.rdbuf();
  return content.str();
}

TEST(StackConfigTest, EmbeddedDefaultIsDeployLocalYaml) {
  absl::StatusOr<StackConfig> file =
      LoadStackConfig(std::string(SEMNAV_SOURCE_DIR) + "/deploy/local.yaml");
  ASSERT_TRUE(file.ok()) << file.status();
  StackConfig embedded = DefaultStackConfig();
  ASSERT_EQ(file->services.size(), 5u);
  ASSERT_EQ(embedded.services.size(), file->services.size());
  for (std::size_t i = 0; i < embedded.services.size(); ++i) {
    EXPECT_EQ(embedded.services[i].name, file->services[i].name);
    EXPECT_EQ(embedded.services[i].binary, file->services[i].binary);
    EXPECT_EQ(embedded.services[i].listen, file->services[i].listen);
    EXPECT_EQ(ReadFile(embedded.services[i].config), ReadFile(file->services[i].config))
        << embedded.services[i].name;
  }
  EXPECT_EQ(embedded.startup_timeout_s, file->startup_timeout_s);
}

TEST(StackConfigTest, RelativeServiceConfigResolvesAgainstTheStackFile) {
  const auto dir = std::filesystem::temp_directory_path() / "semnav_stack_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "stack.yaml") << "services:\n  mapping: {binary: semnav-mapping, listen: "
                                       "'127.0.0.1:1', config: conf/mapping.yaml}\n";
  absl::StatusOr<StackConfig> stack = LoadStackConfig((dir / "stack.yaml").string());
  ASSERT_TRUE(stack.ok()) << stack.status();
  EXPECT_EQ(stack->services[0].config, (dir / "conf/mapping.yaml").string());
}

TEST(StackConfigTest, InlineSettingsBecomeTheServiceConfigFile) {
  const auto path = std::filesystem::temp_directory_path() / "semnav_stack_settings.yaml";
  std::ofstream(path) << "services:\n  gateway:\n    binary: semnav-gateway\n    listen: "
                         "'127.0.0.1:1'\n    settings: {gateway: {mapping: {address: 'h:2'}}}\n";
  absl::StatusOr<StackConfig> stack = LoadStackConfig(path.string());
  ASSERT_TRUE(stack.ok()) << stack.status();
  absl::StatusOr<ConfigReader> written = ConfigReader::FromFile(stack->services[0].config);
  ASSERT_TRUE(written.ok()) << written.status();
  std::string address;
  written->Child("gateway").Child("mapping").Read("address", &address);
  EXPECT_EQ(address, "h:2");
}

TEST(StackConfigTest, TheSettingsFolderLivesAsLongAsTheConfig) {
  // Every parse used to leave a folder behind: the config fuzzer's ctest run left 1,668.
  const auto path = std::filesystem::temp_directory_path() / "semnav_stack_folder.yaml";
  std::ofstream(path) << "services:\n  gateway:\n    binary: semnav-gateway\n    listen: "
                         "'127.0.0.1:1'\n    settings: {gateway: {}}\n";
  std::filesystem::path folder;
  {
    absl::StatusOr<StackConfig> stack = LoadStackConfig(path.string());
    ASSERT_TRUE(stack.ok()) << stack.status();
    const StackConfig copy = *stack;
    stack = absl::UnknownError("the first config is gone");
    folder = std::filesystem::path(copy.services[0].config).parent_path();
    EXPECT_TRUE(std::filesystem::exists(copy.services[0].config));  // the copy holds it
  }
  EXPECT_FALSE(std::filesystem::exists(folder));
  // A refused stack leaves nothing either: no folder of this process is left.
  std::ofstream(path) << "services:\n  gateway:\n    binary: semnav-gateway\n    listen: "
                         "'127.0.0.1:1'\n    settings: {gateway: {}}\n    bogus: 1\n";
  EXPECT_FALSE(LoadStackConfig(path.string()).ok());
  const std::string ours = absl::StrCat("semnav-stack-", ::getpid(), "-");
  for (const auto& entry : std::filesystem::directory_iterator(folder.parent_path())) {
    EXPECT_FALSE(entry.path().filename().string().starts_with(ours)) << entry.path();
  }
}

TEST(StackConfigTest, ConfigFileAndInlineSettingsTogetherAreRefused) {
  const auto path = std::filesystem::temp_directory_path() / "semnav_stack_both.yaml";
  std::ofstream(path) << "services:\n  mapping: {binary: semnav-mapping, listen: 'h:1', config: "
                         "m.yaml, settings: {mapping: {}}}\n";
  EXPECT_THAT(LoadStackConfig(path.string()).status().message(),
              HasSubstr("services.mapping.settings: give a config file or inline settings"));
}

TEST(StackConfigTest, MissingListenAndUnknownKeysAreNamed) {
  const auto path = std::filesystem::temp_directory_path() / "semnav_stack_bad.yaml";
  std::ofstream(path) << "services:\n  mapping: {binary: semnav-mapping, port: 5}\n";
  absl::StatusOr<StackConfig> stack = LoadStackConfig(path.string());
  EXPECT_EQ(stack.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(stack.status().message(), HasSubstr("services.mapping.listen: is required"));
  EXPECT_THAT(stack.status().message(), HasSubstr("services.mapping.port: unknown key"));
}

}  // namespace
}  // namespace semnav::launcher
