#include "services/modelproxy/server/proxy_config.h"

#include <gtest/gtest.h>

#include "absl/strings/match.h"

namespace semnav::modelproxy {
namespace {

absl::StatusOr<BuiltProxy> Build(const std::string& yaml) {
  absl::StatusOr<ConfigReader> root = ConfigReader::FromString(yaml);
  if (!root.ok()) return root.status();
  ConfigReader section = root->Child("modelproxy");
  return BuildProxyFromConfig(section, ProxyOptions());
}

TEST(ModelProxyConfigTest, EmptyConfigIsTheOfflineOnlyStack) {
  const auto built = Build("{}");
  ASSERT_TRUE(built.ok()) << built.status();
  EXPECT_EQ(built->default_alias, "default");
  EXPECT_EQ(built->server.worker_threads, 64);
  EXPECT_EQ(built->proxy->Aliases().at("default"), std::vector<std::string>{"offline"});
  const auto backends = built->proxy->ListBackends(absl::Now());
  ASSERT_EQ(backends.size(), 1u);
  EXPECT_EQ(backends[0].kind, "offline");
  EXPECT_EQ(backends[0].max_in_flight, 64);
}

TEST(ModelProxyConfigTest, BackendsAndAliasesAreRead) {
  const auto built = Build(R"(
modelproxy:
  backends:
    qwen: {kind: dashscope, base_url: "https://x/api/v1", model: qwen-plus, api_key_env: SEMNAV_UNSET_KEY_VAR,
           max_in_flight: 4}
    local: {base_url: "http://127.0.0.1:11434/v1", model: llama}
  aliases:
    default: [qwen, local, offline]
)");
  ASSERT_TRUE(built.ok()) << built.status();
  EXPECT_EQ(built->proxy->Aliases().at("default").size(), 3u);
  for (const BackendStatus& b : built->proxy->ListBackends(absl::Now())) {
    if (b.name == "qwen") {
      EXPECT_EQ(b.kind, "dashscope");
      EXPECT_EQ(b.max_in_flight, 4);
      EXPECT_FALSE(b.configured);  // key variable not set
    }
    if (b.name == "local") {
      EXPECT_TRUE(b.configured);  // no key needed
    }
  }
}

TEST(ModelProxyConfigTest, ErrorsNameTheirKeyPath) {
  const auto bad_kind = Build("modelproxy: {backends: {x: {kind: gemini, base_url: u, model: m}}}");
  EXPECT_EQ(bad_kind.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_TRUE(
      absl::StrContains(bad_kind.status().message(), "modelproxy.backends.x: kind: 'gemini'"))
      << bad_kind.status();
  const auto bad_alias = Build("modelproxy: {aliases: {default: [offline, ghost]}}");
  EXPECT_TRUE(absl::StrContains(bad_alias.status().message(), "unknown backend 'ghost'"))
      << bad_alias.status();
  const auto no_default = Build("modelproxy: {default_alias: main, aliases: {other: [offline]}}");
  EXPECT_TRUE(absl::StrContains(no_default.status().message(), "modelproxy.default_alias"));
  const auto bad_retry = Build("modelproxy: {offline: {retry: {max_attempts: 0}}}");
  EXPECT_TRUE(
      absl::StrContains(bad_retry.status().message(), "retry.max_attempts must be in [1, 10]"))
      << bad_retry.status();
  const auto typo = Build("modelproxy: {cache: {capacty: 5}}");
  EXPECT_TRUE(absl::StrContains(typo.status().message(), "modelproxy.cache.capacty"))
      << typo.status();
}

}  // namespace
}  // namespace semnav::modelproxy
