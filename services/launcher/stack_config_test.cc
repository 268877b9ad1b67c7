#include "services/launcher/stack_config.h"

#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace semnav::launcher {
namespace {

using ::testing::HasSubstr;

TEST(StackConfigTest, EmbeddedDefaultIsDeployLocalYaml) {
  absl::StatusOr<StackConfig> file = LoadStackConfig(std::string(SEMNAV_SOURCE_DIR) + "/deploy/local.yaml");
  ASSERT_TRUE(file.ok()) << file.status();
  StackConfig embedded = DefaultStackConfig();
  ASSERT_EQ(file->services.size(), 5u);
  ASSERT_EQ(embedded.services.size(), file->services.size());
  for (std::size_t i = 0; i < embedded.services.size(); ++i) {
    EXPECT_EQ(embedded.services[i].name, file->services[i].name);
    EXPECT_EQ(embedded.services[i].binary, file->services[i].binary);
    EXPECT_EQ(embedded.services[i].listen, file->services[i].listen);
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
