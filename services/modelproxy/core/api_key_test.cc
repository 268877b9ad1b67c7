#include "services/modelproxy/core/api_key.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <fstream>

namespace semnav::modelproxy {
namespace {

std::string WriteKeyFile(const std::string& name, mode_t mode) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << "sk-file-secret\n";
  ::chmod(path.c_str(), mode);
  return path;
}

TEST(ModelProxyApiKeyTest, FileMustBeOwnerOnlyAndErrorsNeverShowTheKey) {
  const auto ok = ApiKey::FromFile(WriteKeyFile("key600", 0600));
  ASSERT_TRUE(ok.ok()) << ok.status();
  EXPECT_EQ(ok->value(), "sk-file-secret");
  const auto loose = ApiKey::FromFile(WriteKeyFile("key644", 0644));
  EXPECT_EQ(loose.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(loose.status().message().find("sk-file-secret"), std::string::npos);
  EXPECT_EQ(ApiKey::FromFile("/nonexistent/key").status().code(), absl::StatusCode::kNotFound);
}

TEST(ModelProxyApiKeyTest, EnvKeyMayBeAbsentAndRedactScrubsIt) {
  ::setenv("SEMNAV_TEST_MODEL_KEY", "sk-env-1234", 1);
  const ApiKey key = ApiKey::FromEnv("SEMNAV_TEST_MODEL_KEY");
  EXPECT_EQ(key.value(), "sk-env-1234");
  EXPECT_EQ(key.source(), "env SEMNAV_TEST_MODEL_KEY");
  EXPECT_EQ(key.Redact("bad key Bearer sk-env-1234!"), "bad key Bearer [redacted]!");
  EXPECT_TRUE(ApiKey::FromEnv("SEMNAV_TEST_UNSET_VARIABLE").empty());
}

}  // namespace
}  // namespace semnav::modelproxy
