#include "services/modelproxy/core/request_validation.h"

#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"

namespace semnav::modelproxy {
namespace {

bool SupportedMime(const std::string& mime) {
  return mime == "image/png" || mime == "image/jpeg" || mime == "image/webp";
}

}  // namespace

absl::Status ValidateCompletionRequest(const CompletionRequest& request) {
  if (request.messages.empty()) return absl::InvalidArgumentError("messages must not be empty");
  bool has_user = false;
  for (size_t i = 0; i < request.messages.size(); ++i) {
    const ChatMessage& message = request.messages[i];
    has_user = has_user || message.role == Role::kUser;
    if (message.parts.empty()) {
      return absl::InvalidArgumentError(absl::StrCat("messages[", i, "].parts must not be empty"));
    }
    for (size_t j = 0; j < message.parts.size(); ++j) {
      const ContentPart& part = message.parts[j];
      const std::string path = absl::StrCat("messages[", i, "].parts[", j, "]");
      if (!part.is_image()) {
        if (!part.image_mime.empty()) {
          return absl::InvalidArgumentError(absl::StrCat(path, ".image.data must not be empty"));
        }
        if (part.text.empty())
          return absl::InvalidArgumentError(absl::StrCat(path, ".text must not be empty"));
        continue;
      }
      if (!SupportedMime(part.image_mime)) {
        return absl::InvalidArgumentError(
            absl::StrCat(path, ".image.mime_type '", part.image_mime,
                         "' is not image/png, image/jpeg or image/webp"));
      }
      if (part.image_data.size() > kMaxImageBytes) {
        return absl::InvalidArgumentError(
            absl::StrCat(path, ".image.data exceeds ", kMaxImageBytes, " bytes"));
      }
      if (message.role != Role::kUser) {
        return absl::InvalidArgumentError(
            absl::StrCat(path, ".image is only allowed in user messages"));
      }
    }
  }
  if (!has_user) return absl::InvalidArgumentError("messages must contain a user message");
  if (request.max_tokens < 0 || request.max_tokens > kMaxTokensLimit) {
    return absl::InvalidArgumentError(
        absl::StrCat("max_tokens must be in [0, ", kMaxTokensLimit, "]"));
  }
  if (!(request.temperature >= 0.0 && request.temperature <= 2.0)) {
    return absl::InvalidArgumentError("temperature must be in [0, 2]");
  }
  if (request.format == ResponseFormat::kJsonSchema) {
    if (!nlohmann::json::parse(request.json_schema, nullptr, false).is_object()) {
      return absl::InvalidArgumentError(
          "json_schema must be a JSON object with RESPONSE_FORMAT_JSON_SCHEMA");
    }
  } else if (!request.json_schema.empty()) {
    return absl::InvalidArgumentError(
        "json_schema is only allowed with RESPONSE_FORMAT_JSON_SCHEMA");
  }
  return absl::OkStatus();
}

absl::Status ValidateEmbeddingRequest(const EmbeddingRequest& request) {
  if (request.texts.empty() || request.texts.size() > kMaxEmbeddingTexts) {
    return absl::InvalidArgumentError(
        absl::StrCat("texts must hold 1..", kMaxEmbeddingTexts, " strings"));
  }
  for (size_t i = 0; i < request.texts.size(); ++i) {
    if (request.texts[i].empty())
      return absl::InvalidArgumentError(absl::StrCat("texts[", i, "] must not be empty"));
  }
  return absl::OkStatus();
}

}  // namespace semnav::modelproxy
