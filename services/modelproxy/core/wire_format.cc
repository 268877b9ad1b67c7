#include "services/modelproxy/core/wire_format.h"

#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace semnav::modelproxy {

std::string RoleName(Role role) {
  switch (role) {
    case Role::kSystem:
      return "system";
    case Role::kAssistant:
      return "assistant";
    case Role::kUser:
      break;
  }
  return "user";
}

std::string DataUrl(const ContentPart& image) {
  return absl::StrCat("data:", image.image_mime, ";base64,", absl::Base64Escape(image.image_data));
}

std::string SystemText(const CompletionRequest& request) {
  std::vector<std::string> texts;
  for (const ChatMessage& message : request.messages) {
    if (message.role != Role::kSystem) continue;
    for (const ContentPart& part : message.parts) {
      if (!part.is_image()) texts.push_back(part.text);
    }
  }
  return absl::StrJoin(texts, "\n\n");
}

std::vector<std::string> BearerJsonHeaders(const std::string& api_key) {
  std::vector<std::string> headers = {"Content-Type: application/json"};
  if (!api_key.empty()) headers.push_back(absl::StrCat("Authorization: Bearer ", api_key));
  return headers;
}

std::string JsonInstruction(const CompletionRequest& request) {
  switch (request.format) {
    case ResponseFormat::kText:
      return "";
    case ResponseFormat::kJsonObject:
      return "Answer with exactly one JSON object and nothing else.";
    case ResponseFormat::kJsonSchema:
      return absl::StrCat(
          "Answer with exactly one JSON object, nothing else, that validates against this JSON "
          "schema: ",
          request.json_schema);
  }
  return "";
}

}  // namespace semnav::modelproxy
