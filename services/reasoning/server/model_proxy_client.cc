#include "services/reasoning/server/model_proxy_client.h"

#include <chrono>

#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"
#include "services/common/logging/log.h"
#include "services/common/status/grpc_status.h"

namespace semnav::reasoning {
namespace {

namespace pb = ::semnav::modelproxy::v1;

void SetTimeout(int milliseconds, google::protobuf::Duration* out) {
  out->set_seconds(milliseconds / 1000);
  out->set_nanos((milliseconds % 1000) * 1000000);
}

void AddText(pb::ChatMessage* message, const std::string& text) {
  message->add_parts()->set_text(text);
}

// The answer object; the proxy's `offline` flag is copied into it when the JSON lacks it, so the
// slow path weighs prior answers lower either way.
absl::StatusOr<std::string> AnswerJson(const pb::CompleteResponse& response) {
  const std::string& text = response.json().empty() ? response.text() : response.json();
  if (!response.offline()) return text;
  nlohmann::json answer = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!answer.is_object()) return absl::InvalidArgumentError("answer: not a JSON object");
  answer["offline"] = true;
  return answer.dump();
}

// The proxy's latency for the call (0 for a failed one) into the caller's slot, if it has one.
void ReportLatency(const google::protobuf::Duration& latency, absl::Duration* out) {
  if (out != nullptr) *out = absl::Seconds(latency.seconds()) + absl::Nanoseconds(latency.nanos());
}

}  // namespace

ModelProxyClient::ModelProxyClient(std::shared_ptr<grpc::Channel> channel, ModelSettings settings)
    : stub_(pb::ModelProxyService::NewStub(std::move(channel))), settings_(std::move(settings)) {
  for (int i = 0; i < settings_.max_in_flight; ++i) workers_.emplace_back([this] { Work(); });
}

ModelProxyClient::~ModelProxyClient() { Stop(); }

void ModelProxyClient::Stop() {
  {
    absl::MutexLock lock(&mu_);
    stopping_ = true;
    for (grpc::ClientContext* context : active_) context->TryCancel();
  }
  for (std::thread& worker : workers_) {
    if (worker.joinable()) worker.join();
  }
}

void ModelProxyClient::Enqueue(const ModelCaller& caller, Job job) {
  absl::MutexLock lock(&mu_);
  if (!stopping_) queue_.emplace_back(caller, std::move(job));
}

void ModelProxyClient::Work() {
  while (true) {
    grpc::ClientContext context;
    Job job;
    {
      absl::MutexLock lock(&mu_);
      mu_.Await(absl::Condition(
          +[](ModelProxyClient* self) ABSL_EXCLUSIVE_LOCKS_REQUIRED(self->mu_) {
            return self->stopping_ || !self->queue_.empty();
          },
          this));
      if (queue_.empty()) return;  // stopping, and every queued call has had its answer
      // Once stopping, queued calls still run, cancelled before they start, so that every
      // caller gets its CANCELLED answer.
      if (stopping_) context.TryCancel();
      context.AddMetadata("x-semnav-robot-id", queue_.front().first.robot_id);
      context.AddMetadata("x-semnav-task-id", queue_.front().first.task_id);
      job = std::move(queue_.front().second);
      queue_.pop_front();
      active_.insert(&context);
    }
    context.set_deadline(std::chrono::system_clock::now() +
                         std::chrono::milliseconds(settings_.deadline_ms));
    job(context);
    absl::MutexLock lock(&mu_);
    active_.erase(&context);
  }
}

void ModelProxyClient::Complete(const ModelCaller& caller, pb::CompleteRequest call,
                                std::function<void(absl::StatusOr<pb::CompleteResponse>)> done) {
  SetTimeout(settings_.deadline_ms, call.mutable_timeout());
  Enqueue(caller, [this, call = std::move(call), latency = caller.reported_latency,
                   done = std::move(done)](grpc::ClientContext& context) {
    pb::CompleteResponse response;
    const grpc::Status status = stub_->Complete(&context, call, &response);
    ReportLatency(response.latency(), latency.get());
    if (!status.ok()) {
      LogInfo("model_call_failed", {{"rpc", "Complete"},
                                    {"alias", call.model_alias()},
                                    {"code", static_cast<int>(status.error_code())},
                                    {"message", status.error_message()}});
      done(FromGrpcStatus(status));
      return;
    }
    done(std::move(response));
  });
}

void ModelProxyClient::CompleteTask(const ModelCaller& caller, const std::string& prose,
                                    const std::string& task_json, std::string_view schema,
                                    AnswerDone done) {
  pb::CompleteRequest call;
  call.set_model_alias(settings_.model_alias);
  pb::ChatMessage* message = call.add_messages();
  message->set_role(pb::ROLE_USER);
  AddText(message, prose);
  AddText(message, task_json);  // last part: the task object the offline backend reads
  call.set_response_format(pb::RESPONSE_FORMAT_JSON_SCHEMA);
  call.set_json_schema(std::string(schema));
  Complete(caller, std::move(call),
           [done = std::move(done)](absl::StatusOr<pb::CompleteResponse> response) {
             done(response.ok() ? AnswerJson(*response)
                                : absl::StatusOr<std::string>(response.status()));
           });
}

void ModelProxyClient::MatchTarget(const ModelCaller& caller, const ResolveRequest& request,
                                   AnswerDone done) {
  CompleteTask(caller, request.prose, request.task_json, MatchTargetSchema(), std::move(done));
}

void ModelProxyClient::Decompose(const ModelCaller& caller, const DecomposeRequest& request,
                                 AnswerDone done) {
  CompleteTask(caller, request.prose, request.task_json, SubgoalsSchema(), std::move(done));
}

void ModelProxyClient::Ask(const ModelCaller& caller, const ModelQuestion& question,
                           AnswerDone done) {
  pb::CompleteRequest call;
  call.set_model_alias(question.png.empty() ? settings_.model_alias : settings_.vision_alias);
  pb::ChatMessage* message = call.add_messages();
  message->set_role(pb::ROLE_USER);
  AddText(message, question.prompt);
  if (!question.png.empty()) {
    common::v1::Image* image = message->add_parts()->mutable_image();
    image->set_encoding(common::v1::IMAGE_ENCODING_PNG);
    image->set_data(question.png);
  }
  call.set_response_format(pb::RESPONSE_FORMAT_TEXT);
  Complete(caller, std::move(call),
           [done = std::move(done)](absl::StatusOr<pb::CompleteResponse> response) {
             done(response.ok() ? absl::StatusOr<std::string>(response->text())
                                : absl::StatusOr<std::string>(response.status()));
           });
}

void ModelProxyClient::EmbedText(const ModelCaller& caller, const std::string& text,
                                 EmbeddingDone done) {
  pb::EmbedRequest call;
  call.set_model_alias(settings_.embedding_alias);
  call.add_texts(text);
  SetTimeout(settings_.deadline_ms, call.mutable_timeout());
  Enqueue(caller, [this, call = std::move(call), latency = caller.reported_latency,
                   done = std::move(done)](grpc::ClientContext& context) {
    bool recently_unavailable;
    {
      absl::MutexLock lock(&mu_);
      recently_unavailable = absl::Now() < embeddings_unavailable_until_;
    }
    // Answers never run under mu_: the caller's answer takes the caller's lock, which it holds
    // while it enqueues (that is, while it takes mu_).
    if (recently_unavailable) {
      done(absl::UnavailableError("the model proxy offers no text embeddings (recently checked)"));
      return;
    }
    pb::EmbedResponse response;
    const grpc::Status status = stub_->Embed(&context, call, &response);
    ReportLatency(response.latency(), latency.get());
    if (!status.ok()) {
      if (status.error_code() == grpc::StatusCode::UNAVAILABLE) {
        absl::MutexLock lock(&mu_);
        embeddings_unavailable_until_ = absl::Now() + absl::Seconds(settings_.embedding_retry_s);
      }
      done(FromGrpcStatus(status));
      return;
    }
    if (response.embeddings_size() != 1) {
      done(absl::InvalidArgumentError(
          absl::StrCat("embeddings: expected 1 vector, got ", response.embeddings_size())));
      return;
    }
    done(std::vector<float>(response.embeddings(0).values().begin(),
                            response.embeddings(0).values().end()));
  });
}

}  // namespace semnav::reasoning
