#include "services/modelproxy/core/openai_wire.h"

#include <cmath>
#include <limits>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "services/modelproxy/core/json_util.h"

namespace semnav::modelproxy {
namespace {

nlohmann::json MessageContent(const ChatMessage& message) {
  if (message.parts.size() == 1 && !message.parts[0].is_image()) return message.parts[0].text;
  nlohmann::json parts = nlohmann::json::array();
  for (const ContentPart& part : message.parts) {
    if (part.is_image()) {
      parts.push_back({{"type", "image_url"}, {"image_url", {{"url", DataUrl(part)}}}});
    } else {
      parts.push_back({{"type", "text"}, {"text", part.text}});
    }
  }
  return parts;
}

}  // namespace

std::vector<std::string> OpenAiWire::Headers(const std::string& api_key) const {
  return BearerJsonHeaders(api_key);
}

std::string OpenAiWire::ChatBody(const CompletionRequest& request, const std::string& model,
                                 int default_max_tokens) const {
  nlohmann::json messages = nlohmann::json::array();
  for (const ChatMessage& message : request.messages) {
    messages.push_back({{"role", RoleName(message.role)}, {"content", MessageContent(message)}});
  }
  nlohmann::json body = {
      {"model", model},
      {"messages", std::move(messages)},
      {"temperature", request.temperature},
      {"max_tokens", request.max_tokens > 0 ? request.max_tokens : default_max_tokens}};
  if (request.format == ResponseFormat::kJsonObject) {
    body["response_format"] = {{"type", "json_object"}};
  } else if (request.format == ResponseFormat::kJsonSchema) {
    nlohmann::json schema = nlohmann::json::parse(request.json_schema, nullptr, false);
    body["response_format"] = {
        {"type", "json_schema"},
        {"json_schema",
         {{"name", "semnav_answer"}, {"schema", std::move(schema)}, {"strict", false}}}};
  }
  return body.dump();
}

absl::StatusOr<BackendReply> OpenAiWire::ParseChat(const std::string& body) const {
  absl::StatusOr<nlohmann::json> json = ParseJson(body, "chat completion body");
  if (!json.ok()) return json.status();
  const nlohmann::json& choices = Field(*json, "choices");
  if (!choices.is_array() || choices.empty()) {
    return absl::DataLossError("chat completion body has no choices");
  }
  const nlohmann::json& content = Field(Field(choices[0], "message"), "content");
  BackendReply reply;
  if (content.is_string()) {
    reply.text = content.get<std::string>();
  } else if (content.is_array()) {  // some compatible servers return typed parts
    for (const nlohmann::json& part : content) reply.text += StringField(part, "text");
  }
  if (reply.text.empty()) return absl::DataLossError("chat completion has no answer text");
  reply.model = StringField(*json, "model");
  const nlohmann::json& usage = Field(*json, "usage");
  reply.usage.input_tokens = IntField(usage, "prompt_tokens");
  reply.usage.output_tokens = IntField(usage, "completion_tokens");
  return reply;
}

std::string OpenAiWire::ErrorMessage(const std::string& body) const {
  nlohmann::json json = nlohmann::json::parse(body, nullptr, false);
  const nlohmann::json& error = Field(json, "error");
  return error.is_string() ? error.get<std::string>() : StringField(error, "message");
}

std::string OpenAiWire::EmbeddingsBody(const EmbeddingRequest& request, const std::string& model) {
  return nlohmann::json{{"model", model}, {"input", request.texts}}.dump();
}

absl::StatusOr<EmbeddingReply> OpenAiWire::ParseEmbeddings(const std::string& body,
                                                           size_t expected_count) {
  absl::StatusOr<nlohmann::json> json = ParseJson(body, "embeddings body");
  if (!json.ok()) return json.status();
  const nlohmann::json& data = Field(*json, "data");
  if (!data.is_array() || data.size() != expected_count) {
    return absl::DataLossError(
        absl::StrCat("embeddings body must hold ", expected_count, " vectors"));
  }
  EmbeddingReply reply;
  reply.vectors.resize(expected_count);
  for (size_t i = 0; i < data.size(); ++i) {
    const nlohmann::json& index = Field(data[i], "index");
    const size_t slot = index.is_number_unsigned() ? index.get<size_t>() : i;
    const nlohmann::json& values = Field(data[i], "embedding");
    if (slot >= expected_count || !reply.vectors[slot].empty() || !values.is_array() ||
        values.empty()) {
      return absl::DataLossError(absl::StrCat("embeddings body: bad entry ", i));
    }
    for (const nlohmann::json& v : values) {
      // A number beyond float's range would make the conversion undefined.
      if (!v.is_number() || !(std::abs(v.get<double>()) <= std::numeric_limits<float>::max()))
        return absl::DataLossError(absl::StrCat("embeddings body: bad entry ", i));
      reply.vectors[slot].push_back(v.get<float>());
    }
  }
  for (const std::vector<float>& vector : reply.vectors) {
    if (vector.size() != reply.vectors[0].size()) {
      return absl::DataLossError("embeddings body: vectors differ in dimension");
    }
  }
  reply.model = StringField(*json, "model");
  reply.usage.input_tokens = IntField(Field(*json, "usage"), "prompt_tokens");
  return reply;
}

}  // namespace semnav::modelproxy
