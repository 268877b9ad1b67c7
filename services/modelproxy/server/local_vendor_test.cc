// A locally served OpenAI-compatible model (vLLM, Ollama, llama.cpp server, the simulator's VLM)
// configured the way docs/services/modelproxy.md shows: base URL, model name, no key or a key
// file. Checked against the scripted vendor server.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "services/modelproxy/core/http_backend.h"
#include "services/modelproxy/server/proxy_config.h"
#include "services/modelproxy/testing/fake_vendor_server.h"

namespace semnav::modelproxy {
namespace {

using testing::Action;
using testing::FakeVendorServer;
using testing::Route;

absl::StatusOr<BuiltProxy> Build(const std::string& yaml) {
  absl::StatusOr<ConfigReader> root = ConfigReader::FromString(yaml);
  if (!root.ok()) return root.status();
  ConfigReader section = root->Child("modelproxy");
  return BuildProxyFromConfig(section, ProxyOptions());
}

CompletionRequest Question(const std::string& text) {
  CompletionRequest request;
  request.messages.push_back({Role::kUser, {ContentPart{text, "", ""}}});
  return request;
}

std::string LocalConfig(const std::string& base_url, const std::string& key_line) {
  return absl::StrCat(
      "modelproxy:\n  backends:\n    local:\n      kind: openai\n      base_url: \"", base_url,
      "\"\n      model: qwen2.5-vl-7b-instruct\n", key_line,
      "  aliases:\n    default: [local, offline]\n    vision: [local]\n");
}

TEST(ModelProxyLocalVendorTest, NoKeyServerIsCalledWithoutAuthorization) {
  FakeVendorServer server;
  server.SetDefault(Route::kOpenAiChat, Action::Answer("a mug"));
  absl::StatusOr<BuiltProxy> built = Build(LocalConfig(server.base_url(), ""));
  ASSERT_TRUE(built.ok()) << built.status();
  absl::StatusOr<CompletionResult> result =
      built->proxy->Complete(Question("what is on the table?"), {}, absl::Now() + absl::Seconds(5));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "local");
  EXPECT_EQ(result->reply.text, "a mug");
  const std::vector<testing::SeenRequest> seen = server.seen(Route::kOpenAiChat);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].headers.count("authorization"), 0u);
  EXPECT_NE(seen[0].body.find("\"model\":\"qwen2.5-vl-7b-instruct\""), std::string::npos)
      << seen[0].body;
  // Listed as configured although it has no key.
  for (const BackendStatus& b : built->proxy->ListBackends(absl::Now())) {
    if (b.name == "local") {
      EXPECT_TRUE(b.configured);
    }
  }
}

TEST(ModelProxyLocalVendorTest, KeyFileIsSentAsBearer) {
  FakeVendorServer server;
  const std::string path = absl::StrCat(::testing::TempDir(), "/local_vendor_key");
  std::ofstream(path) << "sk-local-123\n";
  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  absl::StatusOr<BuiltProxy> built =
      Build(LocalConfig(server.base_url(), absl::StrCat("      api_key_file: \"", path, "\"\n")));
  ASSERT_TRUE(built.ok()) << built.status();
  ASSERT_TRUE(built->proxy->Complete(Question("hi"), {}, absl::Now() + absl::Seconds(5)).ok());
  const std::vector<testing::SeenRequest> seen = server.seen(Route::kOpenAiChat);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].headers.at("authorization"), "Bearer sk-local-123");
  std::remove(path.c_str());
}

TEST(ModelProxyLocalVendorTest, DownLocalServerFallsBackToOffline) {
  std::string base_url;
  {
    FakeVendorServer gone;  // a port nobody listens on once it is destroyed
    base_url = gone.base_url();
  }
  absl::StatusOr<BuiltProxy> built = Build(LocalConfig(base_url, ""));
  ASSERT_TRUE(built.ok()) << built.status();
  CompletionRequest request = Question(
      R"({"task": "match_target", "target": "cup", "candidates": [{"id": "1", "label": "cup"}]})");
  request.format = ResponseFormat::kJsonObject;
  absl::StatusOr<CompletionResult> result =
      built->proxy->Complete(request, {}, absl::Now() + absl::Seconds(5));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "offline");
}

// A simulated vendor states its (simulated) latency; a real one's is measured.
TEST(ModelProxyLocalVendorTest, StatedLatencyReplacesTheMeasuredOne) {
  FakeVendorServer server;
  server.Script(
      Route::kOpenAiChat,
      {Action::Answer("Code: B2A, Description: x").WithHeader(kSimulatedLatencyHeader, "2.5"),
       Action::Answer("measured"),
       Action::Answer("bad").WithHeader(kSimulatedLatencyHeader, "nan")});
  absl::StatusOr<BuiltProxy> built =
      Build(LocalConfig(server.base_url(), "") + "  cache: {capacity: 0}\n");
  ASSERT_TRUE(built.ok()) << built.status();
  absl::StatusOr<CompletionResult> stated =
      built->proxy->Complete(Question("one"), {}, absl::Now() + absl::Seconds(5));
  ASSERT_TRUE(stated.ok()) << stated.status();
  EXPECT_EQ(stated->latency, absl::Seconds(2.5));
  ASSERT_FALSE(stated->attempts.empty());
  EXPECT_EQ(stated->attempts.back().latency, absl::Seconds(2.5));
  for (const char* text : {"two", "three"}) {
    absl::StatusOr<CompletionResult> measured =
        built->proxy->Complete(Question(text), {}, absl::Now() + absl::Seconds(5));
    ASSERT_TRUE(measured.ok()) << measured.status();
    EXPECT_LT(measured->latency, absl::Seconds(2)) << text;
    EXPECT_GT(measured->latency, absl::ZeroDuration()) << text;
  }
}

}  // namespace
}  // namespace semnav::modelproxy
