// Contract tests: the real semnav-model-proxy binary on a loopback port, called through the
// generated stubs; cloud backends point at a scripted local vendor server in this process.
#include <fcntl.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"
#include "semnav/modelproxy/v1/modelproxy.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "services/modelproxy/testing/fake_vendor_server.h"
#include "tests/support/service_process.h"

namespace semnav::modelproxy {
namespace {

using testing::Action;
using testing::FakeVendorServer;
using testing::Route;

constexpr char kKey[] = "sk-contract-KEY-9876543210";
constexpr char kTask[] =
    R"({"task":"rank_regions","target":"toilet","regions":[{"id":"k","name":"kitchen"},{"id":"b","name":"bathroom"}]})";

v1::CompleteRequest TaskRequest(const std::string& alias = "") {
  v1::CompleteRequest r;
  r.set_model_alias(alias);
  r.set_response_format(v1::RESPONSE_FORMAT_JSON_OBJECT);
  v1::ChatMessage* m = r.add_messages();
  m->set_role(v1::ROLE_USER);
  m->add_parts()->set_text(kTask);
  return r;
}

std::string WriteConfig(const std::string& base_url) {
  const std::string path = ::testing::TempDir() + "modelproxy_contract.yaml";
  std::ofstream(path) << "modelproxy:\n"
                      << "  backends:\n"
                      << "    cloud:\n"
                      << "      kind: openai\n"
                      << "      base_url: " << base_url << "\n"
                      << "      model: gpt-4o-mini\n"
                      << "      api_key_env: SEMNAV_CONTRACT_OPENAI_KEY\n"
                      << "      retry: {max_attempts: 2, initial_backoff_ms: 5}\n"
                      << "  aliases:\n"
                      << "    default: [cloud, offline]\n"
                      << "    cloud-only: [cloud]\n"
                      << "    embed: [cloud]\n";
  return path;
}

class ModelProxyContractTest : public ::testing::Test {
 protected:
  // Starts the binary with `args`; its stderr (logs) goes to log_path_.
  void Start(std::vector<std::string> args) {
    ::setenv("SEMNAV_CONTRACT_OPENAI_KEY", kKey, 1);
    log_path_ = ::testing::TempDir() + "modelproxy_contract.log";
    const int log_fd = ::open(log_path_.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0600);
    const int saved = ::dup(STDERR_FILENO);
    ::dup2(log_fd, STDERR_FILENO);  // the child inherits stderr
    auto process = semnav::testing::ServiceProcess::Start("semnav-model-proxy", std::move(args));
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    ::close(log_fd);
    ASSERT_TRUE(process.ok()) << process.status();
    process_ = *std::move(process);
    stub_ = v1::ModelProxyService::NewStub(process_->channel());
  }

  grpc::Status Complete(const v1::CompleteRequest& request, v1::CompleteResponse* response,
                        const std::string& robot = "robot-1") {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(5));
    context.AddMetadata("x-semnav-robot-id", robot);
    context.AddMetadata("x-semnav-task-id", "task-1");
    return stub_->Complete(&context, request, response);
  }

  v1::GetUsageResponse Usage() {
    grpc::ClientContext context;
    v1::GetUsageResponse response;
    EXPECT_TRUE(stub_->GetUsage(&context, v1::GetUsageRequest(), &response).ok());
    return response;
  }

  std::string Logs() {
    std::ifstream in(log_path_);
    std::stringstream content;
    content << in.rdbuf();
    return content.str();
  }

  FakeVendorServer vendor_;
  std::unique_ptr<semnav::testing::ServiceProcess> process_;
  std::unique_ptr<v1::ModelProxyService::Stub> stub_;
  std::string log_path_;
};

TEST_F(ModelProxyContractTest, OfflineDefaultAnswersStructuredTasksWithProvenance) {
  Start({});
  v1::CompleteResponse response;
  const grpc::Status status = Complete(TaskRequest(), &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_TRUE(response.offline());
  EXPECT_EQ(response.backend(), "offline");
  EXPECT_EQ(response.model(), "conceptnet-atlocation-prior");
  EXPECT_TRUE(absl::StrContains(response.provenance(), "CC BY-SA 4.0"));
  const nlohmann::json answer = nlohmann::json::parse(response.json());
  EXPECT_EQ(answer["best_id"], "b");
  EXPECT_DOUBLE_EQ(answer["confidence"].get<double>(), 0.8);

  grpc::ClientContext context;
  v1::ListBackendsResponse backends;
  ASSERT_TRUE(stub_->ListBackends(&context, v1::ListBackendsRequest(), &backends).ok());
  ASSERT_EQ(backends.backends_size(), 1);
  EXPECT_EQ(backends.backends(0).kind(), "offline");
  EXPECT_EQ(backends.default_alias(), "default");
  EXPECT_EQ(backends.cache_entries(), 1);  // the answer above
  ASSERT_EQ(backends.aliases_size(), 1);
  EXPECT_EQ(backends.aliases(0).chain(0), "offline");
}

// Issue 15 through the real proxy with no vendor: a complex Chinese instruction is decomposed,
// and open-vocabulary targets resolve to a detector class or a place.
TEST_F(ModelProxyContractTest, OfflineDecomposesAndResolvesOpenVocabularyTargets) {
  Start({});
  auto ask = [&](const std::string& task) {
    v1::CompleteRequest request = TaskRequest();
    request.mutable_messages(0)->mutable_parts(0)->set_text(task);
    v1::CompleteResponse response;
    const grpc::Status status = Complete(request, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
    EXPECT_TRUE(response.offline());
    return nlohmann::json::parse(response.json(), nullptr, false);
  };
  const nlohmann::json plan =
      ask(R"({"task": "decompose", "instruction": "先去厨房，然后找红色的杯子"})");
  ASSERT_EQ(plan["subgoals"].size(), 2u);
  EXPECT_EQ(plan["subgoals"][0]["type"], "NAVIGATE");
  EXPECT_EQ(plan["subgoals"][0]["target"], "kitchen");
  EXPECT_EQ(plan["subgoals"][1]["type"], "FIND");
  EXPECT_EQ(plan["subgoals"][1]["target"], "cup");
  EXPECT_EQ(plan["subgoals"][1]["colours"], nlohmann::json::array({"red"}));
  const nlohmann::json cabinet = ask(
      R"({"task": "match_target", "target": "灭火器箱",
          "candidates": [{"id": "7", "label": "door"}, {"id": "9", "label": "fire extinguisher"}]})");
  EXPECT_EQ(cabinet["best_id"], "9");
  // The lexicon names 灭火器, so 灭火器箱 reads "fire extinguisher 箱": the label is the target
  // minus a modifier (0.9), as in English.
  EXPECT_DOUBLE_EQ(cabinet["confidence"].get<double>(), 0.9);
  const nlohmann::json coffee = ask(
      R"({"task": "rank_regions", "target": "coffee machine",
          "regions": [{"id": "a", "name": "bedroom"}, {"id": "b", "name": "kitchen"}]})");
  EXPECT_EQ(coffee["best_id"], "b");
  EXPECT_EQ(coffee["open_vocabulary"]["place"], "kitchen");
}

TEST_F(ModelProxyContractTest, CloudFailureFallsBackToOfflineAndUsageIsPerCaller) {
  vendor_.SetDefault(Route::kOpenAiChat, Action::Status(503));
  Start({"--config", WriteConfig(vendor_.base_url())});
  v1::CompleteResponse response;
  ASSERT_TRUE(Complete(TaskRequest(), &response, "robot-7").ok());
  EXPECT_EQ(response.backend(), "offline");
  ASSERT_EQ(response.attempts_size(), 3);  // two 503s (max_attempts 2), then offline
  EXPECT_EQ(response.attempts(0).backend(), "cloud");
  EXPECT_EQ(response.attempts(0).code(), "UNAVAILABLE");
  EXPECT_EQ(response.attempts(2).code(), "OK");
  EXPECT_EQ(vendor_.requests(Route::kOpenAiChat), 2);
  EXPECT_EQ(vendor_.seen(Route::kOpenAiChat)[0].headers["authorization"],
            std::string("Bearer ") + kKey);

  vendor_.SetDefault(Route::kOpenAiChat,
                     Action::Answer(R"({"best_id":"b","confidence":0.9,"ranking":[]})"));
  v1::CompleteRequest fresh = TaskRequest();
  fresh.set_bypass_cache(true);
  ASSERT_TRUE(Complete(fresh, &response, "robot-7").ok());
  EXPECT_EQ(response.backend(), "cloud");
  EXPECT_FALSE(response.offline());
  EXPECT_EQ(response.usage().input_tokens(), 13);
  ASSERT_TRUE(Complete(TaskRequest(), &response, "robot-7").ok());
  EXPECT_TRUE(response.cached());

  const v1::GetUsageResponse usage = Usage();
  ASSERT_EQ(usage.records_size(), 2);  // robot-7/task-1 on cloud and on offline
  EXPECT_EQ(usage.records(0).robot_id(), "robot-7");
  EXPECT_EQ(usage.records(0).backend(), "cloud");
  EXPECT_EQ(usage.records(0).calls(), 2);
  EXPECT_EQ(usage.records(0).cached_calls(), 1);
  EXPECT_EQ(usage.records(0).usage().input_tokens(), 13);
  EXPECT_EQ(usage.records(1).backend(), "offline");
}

TEST_F(ModelProxyContractTest, EmbeddingsComeFromTheConfiguredEndpointAndOfflineHasNone) {
  Start({"--config", WriteConfig(vendor_.base_url())});
  grpc::ClientContext context;
  v1::EmbedRequest request;
  request.set_model_alias("embed");
  request.add_texts("a red chair");
  request.add_texts("the kitchen");
  v1::EmbedResponse response;
  const grpc::Status status = stub_->Embed(&context, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_EQ(response.embeddings_size(), 2);
  ASSERT_EQ(response.embeddings(1).values_size(), 3);
  EXPECT_FLOAT_EQ(response.embeddings(1).values(0), 2.0f);  // the fake server's vector for input 1
  EXPECT_EQ(response.backend(), "cloud");
  EXPECT_EQ(nlohmann::json::parse(vendor_.seen(Route::kOpenAiEmbeddings)[0].body)["input"][1],
            "the kitchen");

  grpc::ClientContext offline_context;
  request.set_model_alias("default");  // cloud (chat-capable, also embeds) then offline
  vendor_.SetDefault(Route::kOpenAiEmbeddings, Action::Status(400));
  const grpc::Status none = stub_->Embed(&offline_context, request, &response);
  EXPECT_EQ(none.error_code(), grpc::StatusCode::UNAVAILABLE);
  EXPECT_TRUE(absl::StrContains(none.error_message(), "offline: UNIMPLEMENTED"))
      << none.error_message();
}

TEST_F(ModelProxyContractTest, KeyNeverAppearsInErrorsOrLogs) {
  vendor_.SetDefault(Route::kOpenAiChat, Action::EchoKey());
  Start({"--config", WriteConfig(vendor_.base_url())});
  v1::CompleteResponse response;
  const grpc::Status status = Complete(TaskRequest("cloud-only"), &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAVAILABLE);
  EXPECT_TRUE(absl::StrContains(status.error_message(), "[redacted]")) << status.error_message();
  EXPECT_FALSE(absl::StrContains(status.error_message(), kKey));
  grpc::ClientContext context;
  v1::ListBackendsResponse backends;
  ASSERT_TRUE(stub_->ListBackends(&context, v1::ListBackendsRequest(), &backends).ok());
  for (const auto& b : backends.backends()) EXPECT_FALSE(absl::StrContains(b.last_error(), kKey));
  ASSERT_TRUE(process_->Terminate().ok());
  const std::string logs = Logs();
  EXPECT_TRUE(absl::StrContains(logs, "model_attempt_failed")) << logs;
  EXPECT_FALSE(absl::StrContains(logs, kKey));
}

TEST_F(ModelProxyContractTest, BadInputIsRejectedNamingTheFieldAndChangesNothing) {
  Start({});
  const v1::GetUsageResponse before = Usage();
  v1::CompleteResponse response;

  v1::CompleteRequest empty;
  grpc::Status status = Complete(empty, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_TRUE(absl::StrContains(status.error_message(), "messages")) << status.error_message();

  v1::CompleteRequest raw = TaskRequest();
  common::v1::Image* image = raw.mutable_messages(0)->add_parts()->mutable_image();
  image->set_encoding(common::v1::IMAGE_ENCODING_RGB8);
  image->set_data("rgb");
  status = Complete(raw, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  const auto info = GetDetail<common::v1::ErrorInfo>(status);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->field(), "messages[0].parts[1].image.encoding");

  v1::CompleteRequest hot = TaskRequest();
  hot.set_temperature(3.0);
  status = Complete(hot, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_TRUE(absl::StrContains(status.error_message(), "temperature"));

  status = Complete(TaskRequest("no-such-alias"), &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_TRUE(absl::StrContains(status.error_message(), "'no-such-alias'"));
  const auto unknown = GetDetail<common::v1::ErrorInfo>(status);
  ASSERT_TRUE(unknown.has_value());
  EXPECT_EQ(unknown->field(), "model_alias");
  EXPECT_EQ(unknown->reason(), "ALIAS_NOT_FOUND");

  v1::CompleteRequest prose = TaskRequest();
  prose.mutable_messages(0)->mutable_parts(0)->set_text("write me a poem");
  prose.clear_response_format();
  status = Complete(prose, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_TRUE(absl::StrContains(status.error_message(), "messages[-1].parts"));

  // Rejected requests never reached a backend; the failed offline call is accounted.
  const v1::GetUsageResponse after = Usage();
  EXPECT_EQ(before.records_size(), 0);
  ASSERT_EQ(after.records_size(), 1);
  EXPECT_EQ(after.records(0).failed_calls(), 1);
  EXPECT_EQ(after.records(0).calls(), 0);
  ASSERT_TRUE(Complete(TaskRequest(), &response).ok());  // still serving
}

// Hostile requests from other-language clients: NaN, 1e300, 1 MB strings, a PNG header
// claiming 100000 x 100000 pixels, bad timeouts. Each names its field with reason FIELD_INVALID,
// keeps the message short, and no call is accounted (usage unchanged).
TEST_F(ModelProxyContractTest, HostileRequestsNameTheFieldAndChangeNoUsage) {
  Start({});
  v1::CompleteResponse response;
  ASSERT_TRUE(Complete(TaskRequest(), &response).ok());
  const std::string before = Usage().SerializeAsString();
  const std::string megabyte(1 << 20, 'x');
  const auto expect_named = [](const grpc::Status& s, const std::string& field) {
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT)
        << field << ": " << s.error_message();
    const auto info = GetDetail<common::v1::ErrorInfo>(s);
    ASSERT_TRUE(info.has_value()) << field;
    EXPECT_EQ(info->field(), field);
    EXPECT_EQ(info->reason(), "FIELD_INVALID");
    EXPECT_LT(s.error_message().size(), 1024u) << field;
    EXPECT_LT(s.error_details().size(), 2048u) << field;
  };

  v1::CompleteRequest request = TaskRequest();
  request.set_temperature(std::nan(""));
  expect_named(Complete(request, &response), "temperature");
  request = TaskRequest();
  request.set_temperature(1e300);
  expect_named(Complete(request, &response), "temperature");
  request = TaskRequest();
  request.mutable_messages(0)->mutable_parts(0)->set_text(megabyte);
  expect_named(Complete(request, &response), "messages[0].parts[0].text");
  expect_named(Complete(TaskRequest(megabyte), &response), "model_alias");
  request = TaskRequest();
  request.set_response_format(v1::RESPONSE_FORMAT_JSON_SCHEMA);
  request.set_json_schema("{\"d\":\"" + megabyte + "\"}");
  expect_named(Complete(request, &response), "json_schema");
  request = TaskRequest();
  common::v1::Image* bomb = request.mutable_messages(0)->add_parts()->mutable_image();
  bomb->set_encoding(common::v1::IMAGE_ENCODING_PNG);
  // Signature and an IHDR declaring 100000 x 100000 pixels: 40 GB once decoded.
  bomb->set_data(
      std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\x01\x86\xa0\0\x01\x86\xa0\x08\x02\0\0\0", 29));
  expect_named(Complete(request, &response), "messages[0].parts[1].image.data");
  request = TaskRequest();
  request.mutable_timeout()->set_seconds(-5);
  expect_named(Complete(request, &response), "timeout.seconds");
  request = TaskRequest();
  request.mutable_timeout()->set_seconds(4000000000000LL);
  expect_named(Complete(request, &response), "timeout.seconds");
  expect_named(Complete(TaskRequest(), &response, std::string(1000, 'r')), "x-semnav-robot-id");

  v1::EmbedRequest embed;
  embed.set_model_alias("embed");
  embed.add_texts(megabyte);
  v1::EmbedResponse embedded;
  {
    grpc::ClientContext context;
    expect_named(stub_->Embed(&context, embed, &embedded), "texts[0]");
  }
  v1::GetUsageRequest usage;
  usage.set_robot_id(megabyte);
  v1::GetUsageResponse usage_rows;
  {
    grpc::ClientContext context;
    expect_named(stub_->GetUsage(&context, usage, &usage_rows), "robot_id");
  }

  EXPECT_EQ(Usage().SerializeAsString(), before);
}

TEST_F(ModelProxyContractTest, DeadlineHoldsAgainstASlowVendor) {
  vendor_.SetDefault(Route::kOpenAiChat, Action::Answer("late").Slow(absl::Seconds(3)));
  Start({"--config", WriteConfig(vendor_.base_url())});
  v1::CompleteRequest request = TaskRequest("cloud-only");
  request.mutable_timeout()->set_nanos(300 * 1000 * 1000);
  v1::CompleteResponse response;
  const absl::Time start = absl::Now();
  const grpc::Status status = Complete(request, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::DEADLINE_EXCEEDED);
  EXPECT_LT(absl::Now() - start, absl::Milliseconds(600));
}

TEST_F(ModelProxyContractTest, LooseKeyFileRefusesToStart) {
  const std::string key_file = ::testing::TempDir() + "loose_key";
  std::ofstream(key_file) << kKey;
  ::chmod(key_file.c_str(), 0644);
  const std::string config = ::testing::TempDir() + "loose.yaml";
  std::ofstream(config)
      << "modelproxy:\n  backends:\n    cloud:\n      base_url: http://127.0.0.1:1/v1\n"
      << "      model: m\n      api_key_file: " << key_file << "\n";
  const auto result = semnav::testing::RunToCompletion("semnav-model-proxy", {"--config", config});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result->exit_code, 2);
  EXPECT_TRUE(absl::StrContains(result->output, "api_key_file")) << result->output;
  EXPECT_FALSE(absl::StrContains(result->output, kKey));
}

}  // namespace
}  // namespace semnav::modelproxy
