#pragma once
// Anthropic Messages API (POST /v1/messages): system prompt as a top-level field, images as
// base64 source blocks, max_tokens mandatory, no native JSON mode (asked for in the system text).
#include "services/modelproxy/core/wire_format.h"

namespace semnav::modelproxy {

class AnthropicWire : public WireFormat {
 public:
  static constexpr char kApiVersion[] = "2023-06-01";

  std::string ChatPath(const CompletionRequest&) const override { return "/messages"; }
  std::vector<std::string> Headers(const std::string& api_key) const override;
  std::string ChatBody(const CompletionRequest& request, const std::string& model,
                       int default_max_tokens) const override;
  absl::StatusOr<BackendReply> ParseChat(const std::string& body) const override;
  std::string ErrorMessage(const std::string& body) const override;
};

}  // namespace semnav::modelproxy
