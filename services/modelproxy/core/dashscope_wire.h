#pragma once
// DashScope native API (Alibaba Qwen): text-generation and, when images are present,
// multimodal-generation endpoints; body wrapped in input/parameters; answers under
// output.choices with result_format "message". JSON schema is asked for in the system text
// (only json_object is native).
#include "services/modelproxy/core/wire_format.h"

namespace semnav::modelproxy {

class DashScopeWire : public WireFormat {
 public:
  std::string ChatPath(const CompletionRequest& request) const override;
  std::vector<std::string> Headers(const std::string& api_key) const override;
  std::string ChatBody(const CompletionRequest& request, const std::string& model,
                       int default_max_tokens) const override;
  absl::StatusOr<BackendReply> ParseChat(const std::string& body) const override;
  std::string ErrorMessage(const std::string& body) const override;
};

}  // namespace semnav::modelproxy
