#include "services/modelproxy/core/request_key.h"

#include <cmath>

#include "absl/strings/ascii.h"
#include "nlohmann/json.hpp"

namespace semnav::modelproxy {
namespace {

std::string CollapseWhitespace(absl::string_view text) {
  std::string out;
  bool pending_space = false;
  for (char c : absl::StripAsciiWhitespace(text)) {
    if (absl::ascii_isspace(static_cast<unsigned char>(c))) {
      pending_space = true;
      continue;
    }
    if (pending_space) out.push_back(' ');
    pending_space = false;
    out.push_back(c);
  }
  return out;
}

std::string CanonicalSchema(const std::string& schema) {
  nlohmann::json parsed = nlohmann::json::parse(schema, nullptr, /*allow_exceptions=*/false);
  return parsed.is_discarded() ? CollapseWhitespace(schema) : parsed.dump();
}

}  // namespace

std::string NormalizedRequest(const CompletionRequest& request) {
  nlohmann::json messages = nlohmann::json::array();
  for (const ChatMessage& message : request.messages) {
    nlohmann::json parts = nlohmann::json::array();
    for (const ContentPart& part : message.parts) {
      if (part.is_image()) {
        parts.push_back({{"image", Sha256Hex(part.image_data)}, {"mime", part.image_mime}});
      } else {
        parts.push_back({{"text", CollapseWhitespace(part.text)}});
      }
    }
    messages.push_back({{"role", static_cast<int>(message.role)}, {"parts", std::move(parts)}});
  }
  nlohmann::json normalized = {
      {"alias", request.alias},
      {"messages", std::move(messages)},
      {"format", static_cast<int>(request.format)},
      {"schema", request.format == ResponseFormat::kJsonSchema
                     ? CanonicalSchema(request.json_schema)
                     : std::string()},
      {"max_tokens", request.max_tokens},
      {"temperature_milli", std::lround(request.temperature * 1000.0)},
  };
  return normalized.dump();
}

std::string RequestKey(const CompletionRequest& request) {
  return Sha256Hex(NormalizedRequest(request));
}

}  // namespace semnav::modelproxy
