// ModelProxyClient against an in-process server implementing semnav.modelproxy.v1 with scripted
// answers: the request follows the proxy's match_target contract, calls never run inside the
// caller, the deadline holds, offline answers are marked, and a missing embedding backend is not
// asked again within the retry window.
#include "services/reasoning/server/model_proxy_client.h"

#include <grpcpp/grpcpp.h>

#include "absl/synchronization/notification.h"
#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "services/common/status/grpc_status.h"
#include "services/common/status/retry_after.h"

namespace semnav::reasoning {
namespace {

namespace pb = ::semnav::modelproxy::v1;

class ScriptedProxy final : public pb::ModelProxyService::Service {
 public:
  grpc::Status Complete(grpc::ServerContext* context, const pb::CompleteRequest* request,
                        pb::CompleteResponse* response) override {
    absl::MutexLock lock(&mu);
    last_complete = *request;
    const auto& metadata = context->client_metadata();
    auto robot = metadata.find("x-semnav-robot-id");
    robot_id =
        robot == metadata.end() ? "" : std::string(robot->second.data(), robot->second.size());
    ++completes;
    mu.Await(absl::Condition(&release));
    if (!answer_status.ok()) return answer_status;
    *response = answer;
    return grpc::Status::OK;
  }
  grpc::Status Embed(grpc::ServerContext*, const pb::EmbedRequest*, pb::EmbedResponse*) override {
    absl::MutexLock lock(&mu);
    ++embeds;
    return grpc::Status(grpc::StatusCode::UNAVAILABLE, "offline: UNIMPLEMENTED");
  }

  absl::Mutex mu;
  bool release = true;
  pb::CompleteRequest last_complete;
  std::string robot_id;
  pb::CompleteResponse answer;
  grpc::Status answer_status;
  int completes = 0;
  int embeds = 0;
};

class GatewayModelProxyClientTest : public ::testing::Test {
 protected:
  void SetUp() override {
    grpc::ServerBuilder builder;
    int port = 0;
    builder.AddListeningPort("127.0.0.1:0", grpc::InsecureServerCredentials(), &port);
    builder.RegisterService(&proxy_);
    server_ = builder.BuildAndStart();
    ASSERT_NE(port, 0);
    settings_.model_alias = "default";
    settings_.deadline_ms = 1500;
    channel_ = grpc::CreateChannel("127.0.0.1:" + std::to_string(port),
                                   grpc::InsecureChannelCredentials());
  }
  void TearDown() override {
    {
      absl::MutexLock lock(&proxy_.mu);
      proxy_.release = true;
    }
    server_->Shutdown();
  }

  // Runs MatchTarget and waits for its answer.
  absl::StatusOr<std::string> Match(ModelProxyClient& client) {
    absl::Notification done;
    absl::StatusOr<std::string> result;
    client.MatchTarget({"r1", "task-1"}, {"prose", R"({"task":"match_target"})"},
                       [&](absl::StatusOr<std::string> answer) {
                         result = std::move(answer);
                         done.Notify();
                       });
    done.WaitForNotificationWithTimeout(absl::Seconds(10));
    return result;
  }

  ScriptedProxy proxy_;
  std::unique_ptr<grpc::Server> server_;
  std::shared_ptr<grpc::Channel> channel_;
  ModelSettings settings_;
};

TEST_F(GatewayModelProxyClientTest, MatchTargetFollowsTheProxyContractAndMarksOfflineAnswers) {
  proxy_.answer.set_json(R"({"best_id":"7","confidence":0.9,"ranking":[]})");
  proxy_.answer.set_offline(true);
  ModelProxyClient client(channel_, settings_);
  const absl::StatusOr<std::string> answer = Match(client);
  ASSERT_TRUE(answer.ok()) << answer.status();
  const nlohmann::json parsed = nlohmann::json::parse(*answer);
  EXPECT_EQ(parsed["best_id"], "7");
  EXPECT_EQ(parsed["offline"], true);  // copied from CompleteResponse.offline

  absl::MutexLock lock(&proxy_.mu);
  const pb::CompleteRequest& request = proxy_.last_complete;
  EXPECT_EQ(request.model_alias(), "default");
  ASSERT_EQ(request.messages_size(), 1);
  EXPECT_EQ(request.messages(0).role(), pb::ROLE_USER);
  ASSERT_EQ(request.messages(0).parts_size(), 2);
  EXPECT_EQ(request.messages(0).parts(0).text(), "prose");
  EXPECT_EQ(request.messages(0).parts(1).text(),
            R"({"task":"match_target"})");  // last part: the task
  EXPECT_EQ(request.response_format(), pb::RESPONSE_FORMAT_JSON_SCHEMA);
  EXPECT_EQ(request.json_schema(), std::string(MatchTargetSchema()));
  EXPECT_EQ(request.timeout().seconds(), 1);
  EXPECT_EQ(request.timeout().nanos(), 500000000);
  EXPECT_EQ(proxy_.robot_id, "r1");
}

TEST_F(GatewayModelProxyClientTest, DecomposeSendsTheDecomposeTaskWithTheSubgoalsSchema) {
  proxy_.answer.set_json(R"({"subgoals":[{"type":"FIND","target":"cup"}]})");
  ModelProxyClient client(channel_, settings_);
  const DecomposeRequest call = BuildDecomposeRequest("go to the kitchen and find the cup");
  absl::Notification done;
  absl::StatusOr<std::string> answer;
  client.Decompose({"r1", "task-3"}, call, [&](absl::StatusOr<std::string> result) {
    answer = std::move(result);
    done.Notify();
  });
  ASSERT_TRUE(done.WaitForNotificationWithTimeout(absl::Seconds(10)));
  ASSERT_TRUE(answer.ok()) << answer.status();
  EXPECT_EQ(*answer, R"({"subgoals":[{"type":"FIND","target":"cup"}]})");

  absl::MutexLock lock(&proxy_.mu);
  const pb::CompleteRequest& request = proxy_.last_complete;
  ASSERT_EQ(request.messages_size(), 1);
  ASSERT_EQ(request.messages(0).parts_size(), 2);
  EXPECT_EQ(request.messages(0).parts(0).text(), call.prose);
  EXPECT_EQ(request.messages(0).parts(1).text(),
            R"({"instruction":"go to the kitchen and find the cup","task":"decompose"})");
  EXPECT_EQ(request.response_format(), pb::RESPONSE_FORMAT_JSON_SCHEMA);
  EXPECT_EQ(request.json_schema(), std::string(SubgoalsSchema()));
}

TEST_F(GatewayModelProxyClientTest, CallsReturnAtOnceAndTheDeadlineEndsASlowModel) {
  {
    absl::MutexLock lock(&proxy_.mu);
    proxy_.release = false;  // the model never answers
  }
  ModelProxyClient client(channel_, settings_);
  const absl::Time start = absl::Now();
  absl::Notification done;
  absl::StatusOr<std::string> result;
  client.MatchTarget({"r1", "task-1"}, {"prose", "{}"}, [&](absl::StatusOr<std::string> answer) {
    result = std::move(answer);
    done.Notify();
  });
  EXPECT_LT(absl::Now() - start, absl::Milliseconds(100));  // enqueued, not run
  EXPECT_FALSE(done.HasBeenNotified());
  ASSERT_TRUE(done.WaitForNotificationWithTimeout(absl::Seconds(10)));
  const absl::Duration waited = absl::Now() - start;
  EXPECT_EQ(result.status().code(), absl::StatusCode::kDeadlineExceeded) << result.status();
  EXPECT_GE(waited, absl::Milliseconds(1400));
  EXPECT_LT(waited, absl::Seconds(5));
}

TEST_F(GatewayModelProxyClientTest, ErrorsComeBackAsStatusAndStopCancelsPendingCalls) {
  proxy_.answer_status =
      grpc::Status(grpc::StatusCode::INVALID_ARGUMENT, "candidates[1].id 'a' repeats");
  ModelProxyClient client(channel_, settings_);
  const absl::StatusOr<std::string> answer = Match(client);
  EXPECT_EQ(answer.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(answer.status().message(), "candidates[1].id 'a' repeats");

  {
    absl::MutexLock lock(&proxy_.mu);
    proxy_.release = false;
  }
  settings_.deadline_ms = 60000;
  settings_.max_in_flight = 1;
  ModelProxyClient slow(channel_, settings_);
  absl::Notification done;
  absl::StatusCode code = absl::StatusCode::kOk;
  slow.MatchTarget({"r1", "task-1"}, {"prose", "{}"}, [&](absl::StatusOr<std::string> result) {
    code = result.status().code();
    done.Notify();
  });
  absl::StatusCode queued_code = absl::StatusCode::kOk;  // waits behind the first (one worker)
  slow.Ask({"r1", "task-1"}, {"region prompt", ""},
           [&](absl::StatusOr<std::string> result) { queued_code = result.status().code(); });
  for (int i = 0; i < 200; ++i) {  // wait until the call reached the proxy
    absl::MutexLock lock(&proxy_.mu);
    if (proxy_.completes == 2) break;
    proxy_.mu.AwaitWithTimeout(absl::Condition(
                                   +[](int* n) { return *n == 2; }, &proxy_.completes),
                               absl::Milliseconds(50));
  }
  const absl::Time start = absl::Now();
  slow.Stop();
  EXPECT_LT(absl::Now() - start, absl::Seconds(5));
  ASSERT_TRUE(done.HasBeenNotified());
  EXPECT_EQ(code, absl::StatusCode::kCancelled);
  EXPECT_EQ(queued_code, absl::StatusCode::kCancelled);  // every caller gets an answer
  absl::MutexLock lock(&proxy_.mu);
  EXPECT_EQ(proxy_.completes, 2);  // the queued call never reached the proxy
}

// The proxy's gRPC error carries the vendor's Retry-After (ErrorInfo.metadata, written by the
// proxy's ToGrpcStatus); the client hands it to the hub with the error, for its back-off.
TEST_F(GatewayModelProxyClientTest, RetryAfterFromTheProxyComesBackWithTheError) {
  absl::Status limited = absl::UnavailableError("no backend answered; openai: RESOURCE_EXHAUSTED");
  SetRetryAfter(limited, absl::Seconds(12));
  proxy_.answer_status = ToGrpcStatus(limited);
  ModelProxyClient client(channel_, settings_);
  const absl::StatusOr<std::string> answer = Match(client);
  EXPECT_EQ(answer.status().code(), absl::StatusCode::kUnavailable);
  EXPECT_EQ(RetryAfter(answer.status()), absl::Seconds(12));
  proxy_.answer_status = grpc::Status(grpc::StatusCode::UNAVAILABLE, "down");
  EXPECT_FALSE(RetryAfter(Match(client).status()).has_value());
}

TEST_F(GatewayModelProxyClientTest, MissingEmbeddingBackendIsNotAskedAgainWithinTheRetryWindow) {
  ModelProxyClient client(channel_, settings_);
  // The hub asks under its own lock and its answers take that lock. An answer given while the
  // client held its mutex (the cached "unavailable" one did) orders the two locks both ways:
  // the gateway died of that ("potential deadlock") when a second task started in the window.
  absl::Mutex hub;
  for (int i = 0; i < 2; ++i) {
    absl::Notification done;
    absl::StatusCode code = absl::StatusCode::kOk;
    hub.Lock();
    client.EmbedText({"r1", "task-1"}, "red cup",
                     [&](absl::StatusOr<std::vector<float>> embedding) {
                       absl::MutexLock answering(&hub);
                       code = embedding.status().code();
                       done.Notify();
                     });
    hub.Unlock();
    ASSERT_TRUE(done.WaitForNotificationWithTimeout(absl::Seconds(10)));
    EXPECT_EQ(code, absl::StatusCode::kUnavailable);
  }
  absl::MutexLock lock(&proxy_.mu);
  EXPECT_EQ(proxy_.embeds, 1);
}

}  // namespace
}  // namespace semnav::reasoning
