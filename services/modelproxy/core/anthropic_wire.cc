#include "services/modelproxy/core/anthropic_wire.h"

#include "absl/status/status.h"
#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"
#include "services/modelproxy/core/json_util.h"

namespace semnav::modelproxy {

std::vector<std::string> AnthropicWire::Headers(const std::string& api_key) const {
  std::vector<std::string> headers = {"Content-Type: application/json",
                                      absl::StrCat("anthropic-version: ", kApiVersion)};
  if (!api_key.empty()) headers.push_back(absl::StrCat("x-api-key: ", api_key));
  return headers;
}

std::string AnthropicWire::ChatBody(const CompletionRequest& request, const std::string& model,
                                    int default_max_tokens) const {
  nlohmann::json messages = nlohmann::json::array();
  for (const ChatMessage& message : request.messages) {
    if (message.role == Role::kSystem) continue;
    nlohmann::json content = nlohmann::json::array();
    for (const ContentPart& part : message.parts) {
      if (part.is_image()) {
        content.push_back({{"type", "image"},
                           {"source",
                            {{"type", "base64"},
                             {"media_type", part.image_mime},
                             {"data", absl::Base64Escape(part.image_data)}}}});
      } else {
        content.push_back({{"type", "text"}, {"text", part.text}});
      }
    }
    messages.push_back({{"role", RoleName(message.role)}, {"content", std::move(content)}});
  }
  nlohmann::json body = {
      {"model", model},
      {"messages", std::move(messages)},
      {"temperature", request.temperature},
      {"max_tokens", request.max_tokens > 0 ? request.max_tokens : default_max_tokens}};
  std::string system = SystemText(request);
  const std::string json_instruction = JsonInstruction(request);
  if (!json_instruction.empty()) system += (system.empty() ? "" : "\n\n") + json_instruction;
  if (!system.empty()) body["system"] = system;
  return body.dump();
}

absl::StatusOr<BackendReply> AnthropicWire::ParseChat(const std::string& body) const {
  absl::StatusOr<nlohmann::json> json = ParseJson(body, "messages body");
  if (!json.ok()) return json.status();
  const nlohmann::json& content = Field(*json, "content");
  if (!content.is_array()) return absl::DataLossError("messages body has no content array");
  BackendReply reply;
  for (const nlohmann::json& block : content) {
    if (StringField(block, "type") == "text") reply.text += StringField(block, "text");
  }
  if (reply.text.empty()) return absl::DataLossError("messages body has no answer text");
  reply.model = StringField(*json, "model");
  const nlohmann::json& usage = Field(*json, "usage");
  reply.usage.input_tokens = IntField(usage, "input_tokens");
  reply.usage.output_tokens = IntField(usage, "output_tokens");
  return reply;
}

std::string AnthropicWire::ErrorMessage(const std::string& body) const {
  return StringField(Field(nlohmann::json::parse(body, nullptr, false), "error"), "message");
}

}  // namespace semnav::modelproxy
