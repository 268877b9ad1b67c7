#include "services/modelproxy/core/dashscope_wire.h"

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "services/modelproxy/core/json_util.h"

namespace semnav::modelproxy {
namespace {

bool HasImages(const CompletionRequest& request) {
  for (const ChatMessage& message : request.messages) {
    for (const ContentPart& part : message.parts) {
      if (part.is_image()) return true;
    }
  }
  return false;
}

}  // namespace

std::string DashScopeWire::ChatPath(const CompletionRequest& request) const {
  return HasImages(request) ? "/services/aigc/multimodal-generation/generation"
                            : "/services/aigc/text-generation/generation";
}

std::vector<std::string> DashScopeWire::Headers(const std::string& api_key) const {
  return BearerJsonHeaders(api_key);
}

std::string DashScopeWire::ChatBody(const CompletionRequest& request, const std::string& model,
                                    int default_max_tokens) const {
  const bool multimodal = HasImages(request);
  nlohmann::json messages = nlohmann::json::array();
  // One system message: the caller's system text plus, for a schema, the JSON instruction.
  std::string system = SystemText(request);
  if (request.format == ResponseFormat::kJsonSchema) {
    system += (system.empty() ? "" : "\n\n") + JsonInstruction(request);
  }
  if (!system.empty()) {
    messages.push_back({{"role", "system"},
                        {"content", multimodal ? nlohmann::json::array({{{"text", system}}})
                                               : nlohmann::json(system)}});
  }
  for (const ChatMessage& message : request.messages) {
    if (message.role == Role::kSystem) continue;
    nlohmann::json content;
    if (multimodal) {  // multimodal endpoint: list of {"image": url} / {"text": ...}
      content = nlohmann::json::array();
      for (const ContentPart& part : message.parts) {
        content.push_back(part.is_image() ? nlohmann::json{{"image", DataUrl(part)}}
                                          : nlohmann::json{{"text", part.text}});
      }
    } else {
      std::string text;
      for (const ContentPart& part : message.parts) text += part.text;
      content = text;
    }
    messages.push_back({{"role", RoleName(message.role)}, {"content", std::move(content)}});
  }
  nlohmann::json parameters = {
      {"result_format", "message"},
      {"temperature", request.temperature},
      {"max_tokens", request.max_tokens > 0 ? request.max_tokens : default_max_tokens}};
  if (request.format != ResponseFormat::kText) {
    parameters["response_format"] = {{"type", "json_object"}};
  }
  return nlohmann::json{{"model", model},
                        {"input", {{"messages", std::move(messages)}}},
                        {"parameters", std::move(parameters)}}
      .dump();
}

absl::StatusOr<BackendReply> DashScopeWire::ParseChat(const std::string& body) const {
  absl::StatusOr<nlohmann::json> json = ParseJson(body, "generation body");
  if (!json.ok()) return json.status();
  const nlohmann::json& choices = Field(Field(*json, "output"), "choices");
  if (!choices.is_array() || choices.empty()) {
    return absl::DataLossError("generation body has no output.choices");
  }
  const nlohmann::json& content = Field(Field(choices[0], "message"), "content");
  BackendReply reply;
  if (content.is_string()) {
    reply.text = content.get<std::string>();
  } else if (content.is_array()) {  // multimodal answers: [{"text": ...}]
    for (const nlohmann::json& part : content) reply.text += StringField(part, "text");
  }
  if (reply.text.empty()) return absl::DataLossError("generation body has no answer text");
  const nlohmann::json& usage = Field(*json, "usage");
  reply.usage.input_tokens = IntField(usage, "input_tokens");
  reply.usage.output_tokens = IntField(usage, "output_tokens");
  return reply;
}

std::string DashScopeWire::ErrorMessage(const std::string& body) const {
  const nlohmann::json json = nlohmann::json::parse(body, nullptr, false);
  const std::string code = StringField(json, "code");
  const std::string message = StringField(json, "message");
  return code.empty() ? message : absl::StrCat(code, ": ", message);
}

}  // namespace semnav::modelproxy
