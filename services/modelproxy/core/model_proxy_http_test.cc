// ModelProxy over real HTTP: HttpBackends talk to a scripted local vendor server.
#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <thread>

#include "absl/strings/match.h"
#include "nlohmann/json.hpp"
#include "services/common/place_prior/place_prior.h"
#include "services/common/status/field_error.h"
#include "services/common/status/retry_after.h"
#include "services/modelproxy/core/http_backend.h"
#include "services/modelproxy/core/model_proxy.h"
#include "services/modelproxy/core/offline/offline_backend.h"
#include "services/modelproxy/testing/fake_vendor_server.h"

namespace semnav::modelproxy {
namespace {

using testing::Action;
using testing::FakeVendorServer;
using testing::Route;

constexpr char kKey[] = "sk-test-SECRET-0123456789";

BackendPolicy FastPolicy() {
  BackendPolicy p;
  p.timeout = absl::Seconds(2);
  p.retry.max_attempts = 3;
  p.retry.initial_backoff = absl::Milliseconds(5);
  p.retry.max_backoff = absl::Milliseconds(20);
  p.breaker.failure_threshold = 100;
  return p;
}

class ModelProxyHttpTest : public ::testing::Test {
 protected:
  void SetUp() override { ::setenv("SEMNAV_TEST_OPENAI_KEY", kKey, 1); }

  // Backends "openai" and "claude" on the fake server, "offline" from the real prior; alias
  // "default" = openai -> claude, "clip" = openai (embeddings), "json" = openai -> offline.
  void Build(BackendPolicy openai_policy = FastPolicy(), std::string openai_url = "") {
    ProxyOptions options;
    options.on_failed_attempt = [this](const std::string&, const Attempt& a) {
      failed_attempts_.push_back(std::string(a.status.message()));
    };
    proxy_ = std::make_unique<ModelProxy>(options);
    auto transport = std::make_shared<HttpTransport>();
    HttpBackendSpec openai{BackendKind::kOpenAi,
                           openai_url.empty() ? server_.base_url() : openai_url, "gpt-4o-mini", 256,
                           true};
    HttpBackendSpec claude{BackendKind::kAnthropic, server_.base_url(), "claude-3-5-sonnet", 256,
                           true};
    ASSERT_TRUE(proxy_
                    ->AddBackend({"openai", "openai",
                                  std::make_unique<HttpBackend>(
                                      openai, ApiKey::FromEnv("SEMNAV_TEST_OPENAI_KEY"), transport),
                                  openai_policy})
                    .ok());
    ASSERT_TRUE(proxy_
                    ->AddBackend({"claude", "anthropic",
                                  std::make_unique<HttpBackend>(
                                      claude, ApiKey::FromEnv("SEMNAV_TEST_OPENAI_KEY"), transport),
                                  FastPolicy()})
                    .ok());
    auto prior = PlacePrior::Load(PlacePrior::DefaultPath());
    ASSERT_TRUE(prior.ok());
    ASSERT_TRUE(proxy_
                    ->AddBackend({"offline", "offline",
                                  std::make_unique<offline::OfflineBackend>(
                                      *std::move(prior), offline::OfflineParams()),
                                  FastPolicy()})
                    .ok());
    ASSERT_TRUE(proxy_->AddAlias("default", {"openai", "claude"}).ok());
    ASSERT_TRUE(proxy_->AddAlias("clip", {"openai"}).ok());
    ASSERT_TRUE(proxy_->AddAlias("claude-only", {"claude"}).ok());
    ASSERT_TRUE(proxy_->AddAlias("json", {"openai", "offline"}).ok());
  }

  static CompletionRequest Ask(const std::string& text, const std::string& alias = "default") {
    CompletionRequest r;
    r.alias = alias;
    r.messages = {ChatMessage{Role::kUser, {ContentPart{text, "", ""}}}};
    return r;
  }

  absl::StatusOr<CompletionResult> Call(const CompletionRequest& r,
                                        absl::Duration budget = absl::Seconds(5)) {
    return proxy_->Complete(r, CallerId{"robot-1", "task-7"}, absl::Now() + budget);
  }

  FakeVendorServer server_;
  std::unique_ptr<ModelProxy> proxy_;
  std::vector<std::string> failed_attempts_;
};

TEST_F(ModelProxyHttpTest, PrimaryAnswersWithUsageAndSendsTheKey) {
  Build();
  server_.Script(Route::kOpenAiChat, {Action::Answer("a chair")});
  const auto result = Call(Ask("find a chair"));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->reply.text, "a chair");
  EXPECT_EQ(result->backend, "openai");
  EXPECT_EQ(result->reply.model, "gpt-4o-mini");
  EXPECT_EQ(result->reply.usage.input_tokens, 13);
  EXPECT_EQ(result->reply.usage.output_tokens, 5);
  EXPECT_FALSE(result->cached);
  EXPECT_EQ(result->attempts.size(), 1u);
  ASSERT_EQ(server_.requests(Route::kOpenAiChat), 1);
  EXPECT_EQ(server_.seen(Route::kOpenAiChat)[0].headers["authorization"],
            std::string("Bearer ") + kKey);
  EXPECT_EQ(server_.requests(Route::kAnthropicMessages), 0);
}

TEST_F(ModelProxyHttpTest, MalformedJsonFallsBackToTheNextBackendWithoutRetry) {
  Build();
  server_.Script(Route::kOpenAiChat, {Action::Malformed()});
  server_.Script(Route::kAnthropicMessages, {Action::Answer("from claude")});
  const auto result = Call(Ask("q"));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "claude");
  EXPECT_EQ(result->reply.text, "from claude");
  EXPECT_EQ(result->reply.usage.input_tokens, 11);
  ASSERT_EQ(result->attempts.size(), 2u);
  EXPECT_EQ(result->attempts[0].status.code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 1);
}

TEST_F(ModelProxyHttpTest, TruncatedBodyFallsBack) {
  Build();
  server_.Script(Route::kOpenAiChat, {Action::Truncated()});
  const auto result = Call(Ask("q"));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "claude");
  EXPECT_EQ(result->attempts[0].status.code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 1);
}

TEST_F(ModelProxyHttpTest, TooManyRequestsThenSuccessIsRetriedOnTheSameBackend) {
  Build();
  server_.Script(Route::kOpenAiChat, {Action::Status(429), Action::Answer("second try")});
  const auto result = Call(Ask("q"));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "openai");
  EXPECT_EQ(result->reply.text, "second try");
  ASSERT_EQ(result->attempts.size(), 2u);
  EXPECT_EQ(result->attempts[0].status.code(), absl::StatusCode::kResourceExhausted);
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 2);
}

// A vendor's Retry-After is believed: asked to come back in 30 s with 5 s of deadline left, the
// proxy does not retry at once (the old proxy retried after 5 ms, three times) and the final
// error carries the hint for the caller's back-off.
TEST_F(ModelProxyHttpTest, RetryAfterDelaysTheRetryAndComesBackWithTheError) {
  Build();
  server_.SetDefault(Route::kOpenAiChat, Action::Status(429).WithHeader("Retry-After", "30"));
  const auto result = Call(Ask("q", "clip"));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kUnavailable);
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 1);
  EXPECT_EQ(RetryAfter(result.status()), absl::Seconds(30));
  // A 429 without the header: the proxy's own back-off, retries as before, no hint.
  server_.SetDefault(Route::kOpenAiChat, Action::Status(429));
  CompletionRequest again = Ask("q2", "clip");
  const auto plain = Call(again);
  ASSERT_FALSE(plain.ok());
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 1 + 3);
  EXPECT_FALSE(RetryAfter(plain.status()).has_value());
}

TEST_F(ModelProxyHttpTest, ServerErrorRetriesAreBoundedThenFallBack) {
  Build();
  server_.SetDefault(Route::kOpenAiChat, Action::Status(500));
  const auto result = Call(Ask("q"));
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "claude");
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 3);  // max_attempts
  EXPECT_EQ(result->attempts.size(), 4u);
  EXPECT_EQ(result->attempts[2].status.code(), absl::StatusCode::kUnavailable);
}

TEST_F(ModelProxyHttpTest, SlowPrimaryIsCutAtItsTimeoutAndTheFallbackAnswersInTime) {
  BackendPolicy policy = FastPolicy();
  policy.timeout = absl::Milliseconds(150);
  policy.retry.max_attempts = 1;
  Build(policy);
  server_.SetDefault(Route::kOpenAiChat, Action::Answer("late").Slow(absl::Seconds(2)));
  const absl::Time start = absl::Now();
  const auto result = Call(Ask("q"), absl::Seconds(1));
  const absl::Duration elapsed = absl::Now() - start;
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "claude");
  EXPECT_EQ(result->attempts[0].status.code(), absl::StatusCode::kDeadlineExceeded);
  EXPECT_GE(elapsed, absl::Milliseconds(150));
  EXPECT_LT(elapsed, absl::Milliseconds(600));
}

TEST_F(ModelProxyHttpTest, CallerDeadlineHoldsWhenEveryBackendIsSlow) {
  Build();
  server_.SetDefault(Route::kOpenAiChat, Action::Answer("late").Slow(absl::Seconds(2)));
  server_.SetDefault(Route::kAnthropicMessages, Action::Answer("late").Slow(absl::Seconds(2)));
  const absl::Time start = absl::Now();
  const auto result = Call(Ask("q"), absl::Milliseconds(300));
  const absl::Duration elapsed = absl::Now() - start;
  EXPECT_EQ(result.status().code(), absl::StatusCode::kDeadlineExceeded);
  EXPECT_LT(elapsed, absl::Milliseconds(400));
  EXPECT_GE(elapsed, absl::Milliseconds(290));
}

TEST_F(ModelProxyHttpTest, RepeatedRequestIsServedFromTheCacheAndAccounted) {
  Build();
  ASSERT_TRUE(Call(Ask("same question")).ok());
  const auto second = Call(Ask("same   question "));
  ASSERT_TRUE(second.ok());
  EXPECT_TRUE(second->cached);
  EXPECT_EQ(second->backend, "openai");
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 1);
  CompletionRequest bypass = Ask("same question");
  bypass.bypass_cache = true;
  ASSERT_TRUE(Call(bypass).ok());
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 2);

  const std::vector<UsageRow> rows = proxy_->usage().Query("robot-1", "task-7");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].backend, "openai");
  EXPECT_EQ(rows[0].totals.calls, 3);
  EXPECT_EQ(rows[0].totals.cached_calls, 1);
  EXPECT_EQ(rows[0].totals.input_tokens, 26);
  EXPECT_EQ(rows[0].totals.output_tokens, 10);
}

TEST_F(ModelProxyHttpTest, KeyNeverAppearsInErrorsOrFailureEvents) {
  Build();
  server_.SetDefault(Route::kOpenAiChat, Action::EchoKey());
  server_.SetDefault(Route::kAnthropicMessages, Action::EchoKey());
  const auto result = Call(Ask("q"));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kUnavailable);
  EXPECT_TRUE(
      absl::StrContains(result.status().message(), "HTTP 401: invalid key: Bearer [redacted]"))
      << result.status();
  EXPECT_FALSE(absl::StrContains(result.status().ToString(), kKey));
  ASSERT_EQ(failed_attempts_.size(), 2u);  // 401 is not retried
  for (const std::string& message : failed_attempts_)
    EXPECT_FALSE(absl::StrContains(message, kKey));
  for (const BackendStatus& b : proxy_->ListBackends(absl::Now())) {
    EXPECT_FALSE(absl::StrContains(b.last_error, kKey));
  }
}

TEST_F(ModelProxyHttpTest, CircuitBreakerSkipsADeadBackend) {
  BackendPolicy policy = FastPolicy();
  policy.retry.max_attempts = 1;
  policy.breaker.failure_threshold = 2;
  policy.breaker.open_duration = absl::Seconds(60);
  Build(policy);
  server_.SetDefault(Route::kOpenAiChat, Action::Status(503));
  for (const char* q : {"q1", "q2", "q3"}) ASSERT_TRUE(Call(Ask(q)).ok());
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 2);
  EXPECT_EQ(server_.requests(Route::kAnthropicMessages), 3);
  EXPECT_EQ(failed_attempts_.back(), "circuit open");
  const auto backends = proxy_->ListBackends(absl::Now());  // sorted by name
  ASSERT_EQ(backends.size(), 3u);
  EXPECT_EQ(backends[2].name, "openai");
  EXPECT_EQ(backends[2].breaker, BreakerState::kOpen);
  EXPECT_EQ(backends[2].last_error, "UNAVAILABLE: HTTP 503: scripted 503");
  EXPECT_EQ(backends[2].attempts, 2);
  EXPECT_EQ(backends[2].failures, 2);
  EXPECT_EQ(backends[0].breaker, BreakerState::kClosed);
}

TEST_F(ModelProxyHttpTest, ConcurrencyLimitMakesCallersWaitOnlyUntilTheirDeadline) {
  BackendPolicy policy = FastPolicy();
  policy.max_in_flight = 1;
  policy.retry.max_attempts = 1;
  Build(policy);
  server_.Script(Route::kOpenAiChat, {Action::Answer("slow ok").Slow(absl::Milliseconds(400))});
  absl::StatusOr<CompletionResult> first;
  std::thread t([&] { first = Call(Ask("a")); });
  for (int i = 0; i < 2000 && server_.requests(Route::kOpenAiChat) == 0; ++i)
    absl::SleepFor(absl::Milliseconds(1));
  ASSERT_EQ(server_.requests(Route::kOpenAiChat), 1);  // the only slot is taken now
  const auto second = Call(Ask("b"), absl::Milliseconds(200));
  t.join();
  EXPECT_EQ(second.status().code(), absl::StatusCode::kDeadlineExceeded);
  EXPECT_TRUE(
      absl::StrContains(second.status().message(),
                        "openai: RESOURCE_EXHAUSTED: concurrency limit: no free slot in time"))
      << second.status();
  ASSERT_TRUE(first.ok()) << first.status();
  EXPECT_EQ(first->backend, "openai");
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 1);
}

TEST_F(ModelProxyHttpTest, JsonAnswersAreParsedAndOfflineClosesTheChain) {
  Build(FastPolicy(), "http://127.0.0.1:1/v1");  // nothing listens: connection refused
  CompletionRequest r =
      Ask(R"({"task":"match_target","target":"tv","candidates":[{"id":"x","label":"television"}]})",
          "json");
  r.format = ResponseFormat::kJsonObject;
  const auto result = Call(r);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "offline");
  EXPECT_TRUE(result->reply.offline);
  EXPECT_EQ(result->attempts[0].status.code(), absl::StatusCode::kUnavailable);
  EXPECT_EQ(result->attempts.size(), 2u);  // connection refused is not retried
  EXPECT_EQ(nlohmann::json::parse(result->json)["best_id"], "x");
}

TEST_F(ModelProxyHttpTest, NonJsonAnswerToAJsonRequestFallsBack) {
  Build();
  server_.Script(Route::kOpenAiChat, {Action::Answer("Sure! The best region is r1.")});
  server_.Script(Route::kAnthropicMessages,
                 {Action::Answer("```json\n{\"best_id\": \"r1\"}\n```")});
  CompletionRequest r = Ask("rank");
  r.format = ResponseFormat::kJsonObject;
  const auto result = Call(r);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->backend, "claude");
  EXPECT_EQ(result->json, R"({"best_id":"r1"})");
}

TEST_F(ModelProxyHttpTest, EmbeddingsComeFromTheOpenAiEndpoint) {
  Build();
  const auto result = proxy_->Embed({"clip", {"a red chair", "a sofa"}}, CallerId{},
                                    absl::Now() + absl::Seconds(5));
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_EQ(result->reply.vectors.size(), 2u);
  EXPECT_EQ(result->reply.vectors[1], (std::vector<float>{2.0f, 0.5f, -0.25f}));
  EXPECT_EQ(result->reply.usage.input_tokens, 6);
  const auto none =
      proxy_->Embed({"claude-only", {"x"}}, CallerId{}, absl::Now() + absl::Seconds(5));
  EXPECT_EQ(none.status().code(), absl::StatusCode::kUnavailable);
  EXPECT_TRUE(absl::StrContains(none.status().message(), "UNIMPLEMENTED"));
}

TEST_F(ModelProxyHttpTest, BadRequestsFailBeforeAnyBackendCall) {
  Build();
  EXPECT_EQ(Call(Ask("q", "nope")).status().code(), absl::StatusCode::kNotFound);
  CompletionRequest r = Ask("q");
  r.temperature = -1;
  EXPECT_EQ(Call(r).status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(server_.requests(Route::kOpenAiChat), 0);
}

// Every call outcome carries a stable reason for ErrorInfo, and a huge alias is not echoed.
TEST_F(ModelProxyHttpTest, FailuresCarryAStableReason) {
  Build();
  const auto unknown = Call(Ask("q", "nope"));
  EXPECT_EQ(ErrorReason(unknown.status()).value_or(""), "ALIAS_NOT_FOUND");
  EXPECT_EQ(ErrorField(unknown.status()).value_or(""), "model_alias");
  const auto huge = Call(Ask("q", std::string(1 << 20, 'a')));
  EXPECT_EQ(huge.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(huge.status()).value_or(""), "model_alias");
  EXPECT_LT(huge.status().message().size(), 200u);
  CompletionRequest hot = Ask("q");
  hot.temperature = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ErrorReason(Call(hot).status()).value_or(""), "FIELD_INVALID");

  server_.SetDefault(Route::kOpenAiChat, Action::Status(503));
  server_.SetDefault(Route::kAnthropicMessages, Action::Status(503));
  const auto down = Call(Ask("q"));
  EXPECT_EQ(down.status().code(), absl::StatusCode::kUnavailable);
  EXPECT_EQ(ErrorReason(down.status()).value_or(""), "BACKEND_UNAVAILABLE");
  const auto late = Call(Ask("q"), absl::ZeroDuration());
  EXPECT_EQ(late.status().code(), absl::StatusCode::kDeadlineExceeded);
  EXPECT_EQ(ErrorReason(late.status()).value_or(""), "DEADLINE_EXCEEDED");
}

}  // namespace
}  // namespace semnav::modelproxy
