#include "services/common/config/secret.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace semnav {
namespace {

std::string WriteFile(const std::string& name, const std::string& content, mode_t mode) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << content;
  ::chmod(path.c_str(), mode);
  return path;
}

TEST(SecretTest, ReadsOwnerOnlyFileTrimmed) {
  const std::string path = WriteFile("semnav_secret_ok", "  s3cret\n", 0600);
  EXPECT_EQ(*ReadSecretFile(path), "s3cret");
}

TEST(SecretTest, WorldReadableFileIsRefusedWithoutEchoingIt) {
  const std::string path = WriteFile("semnav_secret_open", "s3cret", 0644);
  absl::StatusOr<std::string> secret = ReadSecretFile(path);
  EXPECT_EQ(secret.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(std::string(secret.status().message()).find("s3cret"), std::string::npos);
}

TEST(SecretTest, MissingSourcesAreNotFound) {
  EXPECT_EQ(ReadSecretFile("/nonexistent/token").status().code(), absl::StatusCode::kNotFound);
  ::unsetenv("SEMNAV_TEST_UNSET_TOKEN");
  EXPECT_EQ(ReadSecretEnv("SEMNAV_TEST_UNSET_TOKEN").status().code(), absl::StatusCode::kNotFound);
  ::setenv("SEMNAV_TEST_TOKEN", "abc ", 1);
  EXPECT_EQ(*ReadSecretEnv("SEMNAV_TEST_TOKEN"), "abc");
}

}  // namespace
}  // namespace semnav
