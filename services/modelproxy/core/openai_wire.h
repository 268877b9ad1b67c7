#pragma once
// OpenAI-compatible chat completions (OpenAI, DashScope compatible mode, vLLM, Ollama,
// llama.cpp server) and the /embeddings endpoint.
#include "services/modelproxy/core/wire_format.h"

namespace semnav::modelproxy {

class OpenAiWire : public WireFormat {
 public:
  std::string ChatPath(const CompletionRequest&) const override { return "/chat/completions"; }
  std::vector<std::string> Headers(const std::string& api_key) const override;
  std::string ChatBody(const CompletionRequest& request, const std::string& model,
                       int default_max_tokens) const override;
  absl::StatusOr<BackendReply> ParseChat(const std::string& body) const override;
  std::string ErrorMessage(const std::string& body) const override;

  static std::string EmbeddingsPath() { return "/embeddings"; }
  static std::string EmbeddingsBody(const EmbeddingRequest& request, const std::string& model);
  // DATA_LOSS unless there is exactly one non-empty vector per input, all of one dimension.
  static absl::StatusOr<EmbeddingReply> ParseEmbeddings(const std::string& body,
                                                        size_t expected_count);
};

}  // namespace semnav::modelproxy
