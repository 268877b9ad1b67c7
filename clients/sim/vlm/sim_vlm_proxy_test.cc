// The simulated VLM behind the model proxy exactly as a vendor: OpenAI-compatible backend, base
// URL, model name, key; the answer's latency is the simulated one the endpoint states.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>

#include "absl/strings/match.h"
#include "clients/sim/vlm/sim_vlm_server.h"
#include "clients/sim/vlm/sim_vlm_test_world.h"
#include "services/modelproxy/core/http_backend.h"
#include "services/modelproxy/core/model_proxy.h"

namespace semnav::sim::vlm {
namespace {

using namespace semnav::modelproxy;

constexpr char kKeyEnv[] = "SEMNAV_TEST_SIM_VLM_KEY";

std::unique_ptr<ModelProxy> ProxyFor(const std::string& base_url) {
  auto proxy = std::make_unique<ModelProxy>(ProxyOptions());
  HttpBackendSpec spec;
  spec.base_url = base_url;
  spec.model = "sim-vlm";
  spec.require_key = true;
  BackendPolicy policy;
  policy.retry.max_attempts = 1;
  EXPECT_TRUE(proxy
                  ->AddBackend(
                      BackendEntry{"sim", "openai",
                                   std::make_unique<HttpBackend>(spec, ApiKey::FromEnv(kKeyEnv),
                                                                 std::make_shared<HttpTransport>()),
                                   policy})
                  .ok());
  EXPECT_TRUE(proxy->AddAlias("default", {"sim"}).ok());
  return proxy;
}

TEST(SimVlmProxyTest, SearchPromptThroughTheProxyGetsTheCodeAndTheStatedLatency) {
  const World world = testing::SearchWorld();
  FrameLog log;
  const Eigen::Vector3d camera(0, 0, 1.5);
  const SensorFrame frame = testing::Capture(Scene::Build(world), camera, 0.0, 11);
  log.Record(frame);
  SimVlmConfig config;
  config.errors = SimVlmErrors{0, 0, 0, 0};
  config.api_key = "sim-key-1";
  auto model = SimVlm::Create(world, &log, config);
  auto twin = SimVlm::Create(world, &log, config);  // the same model, asked directly
  ASSERT_TRUE(model.ok() && twin.ok());
  absl::StatusOr<std::unique_ptr<SimVlmServer>> server = SimVlmServer::Start(*std::move(model));
  ASSERT_TRUE(server.ok()) << server.status();

  absl::StatusOr<reasoning::EroiSearch> search =
      reasoning::EroiSearch::Create("backpack", testing::GatewayEroi());
  ASSERT_TRUE(search.ok());
  cv::Mat image = frame.rgb->clone();
  const reasoning::EroiObservation observation =
      search->Annotate(camera, testing::BodyOrientation(0.0), testing::Pinhole(), image);
  std::vector<uchar> png;
  cv::imencode(".png", image, png);
  CompletionRequest request;
  request.messages.push_back({Role::kUser,
                              {ContentPart{observation.prompt, "", ""},
                               ContentPart{"", std::string(png.begin(), png.end()), "image/png"}}});

  ::setenv(kKeyEnv, "sim-key-1", 1);
  std::unique_ptr<ModelProxy> proxy = ProxyFor((*server)->base_url());
  absl::StatusOr<CompletionResult> result =
      proxy->Complete(request, {"robot", "task"}, absl::Now() + absl::Seconds(10));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(absl::StrContains(result->reply.text, "Description: backpack seen here"))
      << result->reply.text;
  const absl::StatusOr<VlmReply> direct = (*twin)->Answer({observation.prompt, {image}});
  ASSERT_TRUE(direct.ok());
  EXPECT_EQ(result->reply.text, direct->text);
  EXPECT_EQ(result->latency, absl::Seconds(direct->latency_s));
  EXPECT_EQ(result->reply.usage.input_tokens, 1083);
  // The bench's per-episode model figures: one answer, about an image, its tokens and time.
  const SimVlmServer::Served served = (*server)->served();
  EXPECT_EQ(served.answers, 1);
  EXPECT_EQ(served.vision_answers, 1);
  EXPECT_EQ(served.tokens, direct->input_tokens + direct->output_tokens);
  EXPECT_EQ(served.latency_ms, std::llround(1000.0 * direct->latency_s));

  ::setenv(kKeyEnv, "wrong-key", 1);
  std::unique_ptr<ModelProxy> wrong = ProxyFor((*server)->base_url());
  request.bypass_cache = true;
  EXPECT_FALSE(wrong->Complete(request, {}, absl::Now() + absl::Seconds(10)).ok());
  ::unsetenv(kKeyEnv);
}

// The endpoint's text encoder on the OpenAI embeddings wire, through the proxy: the vector the
// model gives directly, one per text, counted apart from the chat answers.
TEST(SimVlmProxyTest, EmbeddingsThroughTheProxyAreTheTextEncodersVectors) {
  const World world = testing::SearchWorld();
  FrameLog log;
  SimVlmConfig config;
  config.api_key = "sim-key-2";
  auto model = SimVlm::Create(world, &log, config);
  auto twin = SimVlm::Create(world, &log, config);
  ASSERT_TRUE(model.ok() && twin.ok());
  absl::StatusOr<std::unique_ptr<SimVlmServer>> server = SimVlmServer::Start(*std::move(model));
  ASSERT_TRUE(server.ok()) << server.status();
  ::setenv(kKeyEnv, "sim-key-2", 1);
  std::unique_ptr<ModelProxy> proxy = ProxyFor((*server)->base_url());
  EmbeddingRequest request;
  request.texts = {"backpack", "红色的背包"};
  absl::StatusOr<EmbeddingResult> result =
      proxy->Embed(request, {"robot", "task"}, absl::Now() + absl::Seconds(10));
  ::unsetenv(kKeyEnv);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_EQ(result->reply.vectors.size(), 2u);
  EXPECT_EQ(result->reply.vectors[0], (*twin)->EmbedText("backpack").vector);
  EXPECT_EQ(result->reply.vectors[1], (*twin)->EmbedText("红色的背包").vector);
  EXPECT_EQ(result->reply.usage.input_tokens, (1 + 8 / 4) + (1 + 15 / 4));  // 1 + bytes / 4 each
  const SimVlmServer::Served served = (*server)->served();
  EXPECT_EQ(served.embedding_answers, 1);
  EXPECT_EQ(served.answers, 0);
  // The call takes the encoder's stated (simulated) time, the batch's slowest text, not the
  // proxy's wall time: a simulated robot's episode must not depend on the machine's load.
  const double stated = std::max((*twin)->EmbedText("backpack").latency_s,
                                 (*twin)->EmbedText("红色的背包").latency_s);
  EXPECT_GT(stated, 0.0);
  EXPECT_EQ(result->latency, absl::Seconds(stated));
  EXPECT_EQ(served.latency_ms, std::llround(1000.0 * stated));
}

TEST(SimVlmServerTest, EmbeddingsBodyIsValidatedByField) {
  EXPECT_EQ(*ParseEmbeddingsBody(R"({"model": "m", "input": "cup"})"),
            std::vector<std::string>{"cup"});
  EXPECT_EQ(*ParseEmbeddingsBody(R"({"input": ["cup", "杯子"]})"),
            (std::vector<std::string>{"cup", "杯子"}));
  for (const char* bad : {R"({"input": []})", R"({"input": [3]})", R"({"input": ""})",
                          R"({"model": "m"})", "not json"}) {
    const absl::StatusOr<std::vector<std::string>> parsed = ParseEmbeddingsBody(bad);
    EXPECT_EQ(parsed.status().code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_TRUE(absl::StrContains(parsed.status().message(), "input")) << bad;
  }
}

}  // namespace
}  // namespace semnav::sim::vlm
