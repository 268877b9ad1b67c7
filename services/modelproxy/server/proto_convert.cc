#include "services/modelproxy/server/proto_convert.h"

#include "absl/strings/str_cat.h"
#include "services/common/status/grpc_status.h"

namespace semnav::modelproxy {
namespace {

void SetDuration(absl::Duration d, google::protobuf::Duration* out) {
  const int64_t nanos = absl::ToInt64Nanoseconds(d);
  out->set_seconds(nanos / 1000000000);
  out->set_nanos(static_cast<int32_t>(nanos % 1000000000));
}

Role ToCore(v1::Role role) {
  switch (role) {
    case v1::ROLE_SYSTEM:
      return Role::kSystem;
    case v1::ROLE_ASSISTANT:
      return Role::kAssistant;
    default:
      return Role::kUser;
  }
}

void ToProto(const std::vector<Attempt>& attempts,
             google::protobuf::RepeatedPtrField<v1::Attempt>* out) {
  for (const Attempt& a : attempts) {
    v1::Attempt* p = out->Add();
    p->set_backend(a.backend);
    p->set_code(absl::StatusCodeToString(a.status.code()));
    p->set_message(std::string(a.status.message()));
    SetDuration(a.latency, p->mutable_latency());
  }
}

void ToProto(const Usage& usage, v1::Usage* out) {
  out->set_input_tokens(usage.input_tokens);
  out->set_output_tokens(usage.output_tokens);
}

}  // namespace

absl::StatusOr<CompletionRequest> ToCore(const v1::CompleteRequest& request) {
  CompletionRequest out;
  out.alias = request.model_alias();
  for (int i = 0; i < request.messages_size(); ++i) {
    const v1::ChatMessage& message = request.messages(i);
    if (!v1::Role_IsValid(message.role())) {
      return FieldError(absl::StatusCode::kInvalidArgument, absl::StrCat("messages[", i, "].role"),
                        "unknown role");
    }
    ChatMessage m{ToCore(message.role()), {}};
    for (int j = 0; j < message.parts_size(); ++j) {
      const v1::ContentPart& part = message.parts(j);
      const std::string path = absl::StrCat("messages[", i, "].parts[", j, "]");
      if (part.part_case() == v1::ContentPart::kText) {
        m.parts.push_back(ContentPart{part.text(), "", ""});
      } else if (part.part_case() == v1::ContentPart::kImage) {
        const auto encoding = part.image().encoding();
        if (encoding != common::v1::IMAGE_ENCODING_PNG &&
            encoding != common::v1::IMAGE_ENCODING_JPEG) {
          return FieldError(absl::StatusCode::kInvalidArgument, path + ".image.encoding",
                            "must be IMAGE_ENCODING_PNG or IMAGE_ENCODING_JPEG");
        }
        if (part.image().data().empty()) {
          return FieldError(absl::StatusCode::kInvalidArgument, path + ".image.data",
                            "must not be empty");
        }
        m.parts.push_back(
            ContentPart{"", part.image().data(),
                        encoding == common::v1::IMAGE_ENCODING_PNG ? "image/png" : "image/jpeg"});
      } else {
        return FieldError(absl::StatusCode::kInvalidArgument, path, "must set text or image");
      }
    }
    out.messages.push_back(std::move(m));
  }
  if (!v1::ResponseFormat_IsValid(request.response_format())) {
    return FieldError(absl::StatusCode::kInvalidArgument, "response_format",
                      "unknown response format");
  }
  switch (request.response_format()) {
    case v1::RESPONSE_FORMAT_JSON_OBJECT:
      out.format = ResponseFormat::kJsonObject;
      break;
    case v1::RESPONSE_FORMAT_JSON_SCHEMA:
      out.format = ResponseFormat::kJsonSchema;
      break;
    default:
      out.format = ResponseFormat::kText;
  }
  out.json_schema = request.json_schema();
  out.max_tokens = request.max_tokens();
  out.temperature = request.temperature();
  out.bypass_cache = request.bypass_cache();
  return out;
}

EmbeddingRequest ToCore(const v1::EmbedRequest& request) {
  return EmbeddingRequest{request.model_alias(), {request.texts().begin(), request.texts().end()}};
}

void ToProto(const CompletionResult& result, v1::CompleteResponse* response) {
  response->set_text(result.reply.text);
  response->set_json(result.json);
  ToProto(result.cached ? Usage{} : result.reply.usage, response->mutable_usage());
  response->set_backend(result.backend);
  response->set_model(result.reply.model);
  SetDuration(result.latency, response->mutable_latency());
  response->set_cached(result.cached);
  response->set_offline(result.reply.offline);
  response->set_provenance(result.reply.provenance);
  ToProto(result.attempts, response->mutable_attempts());
}

void ToProto(const EmbeddingResult& result, v1::EmbedResponse* response) {
  for (const std::vector<float>& vector : result.reply.vectors) {
    response->add_embeddings()->mutable_values()->Add(vector.begin(), vector.end());
  }
  response->set_backend(result.backend);
  response->set_model(result.reply.model);
  ToProto(result.reply.usage, response->mutable_usage());
  SetDuration(result.latency, response->mutable_latency());
  ToProto(result.attempts, response->mutable_attempts());
}

void ToProto(const BackendStatus& status, v1::BackendInfo* info) {
  info->set_name(status.name);
  info->set_kind(status.kind);
  info->set_model(status.model);
  info->set_endpoint(status.endpoint);
  info->set_configured(status.configured);
  switch (status.breaker) {
    case BreakerState::kClosed:
      info->set_circuit(v1::CIRCUIT_STATE_CLOSED);
      break;
    case BreakerState::kOpen:
      info->set_circuit(v1::CIRCUIT_STATE_OPEN);
      break;
    case BreakerState::kHalfOpen:
      info->set_circuit(v1::CIRCUIT_STATE_HALF_OPEN);
      break;
  }
  info->set_consecutive_failures(status.consecutive_failures);
  info->set_in_flight(status.in_flight);
  info->set_max_in_flight(status.max_in_flight);
  info->set_attempts(status.attempts);
  info->set_failures(status.failures);
  info->set_last_error(status.last_error);
}

void ToProto(const UsageRow& row, v1::UsageRecord* record) {
  record->set_robot_id(row.robot_id);
  record->set_task_id(row.task_id);
  record->set_backend(row.backend);
  record->set_calls(row.totals.calls);
  record->set_cached_calls(row.totals.cached_calls);
  record->set_failed_calls(row.totals.failed_calls);
  record->mutable_usage()->set_input_tokens(row.totals.input_tokens);
  record->mutable_usage()->set_output_tokens(row.totals.output_tokens);
}

}  // namespace semnav::modelproxy
