#pragma once
// A vendor API over HTTP(S): a wire format, a base URL, a model name and an optional key.
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "services/modelproxy/core/api_key.h"
#include "services/modelproxy/core/backend.h"
#include "services/modelproxy/core/http_transport.h"
#include "services/modelproxy/core/wire_format.h"

namespace semnav::modelproxy {

// Response header in which a simulated vendor (clients/sim/vlm) states the latency of its answer
// in seconds (simulated time); real vendors do not send it and their latency stays measured.
inline constexpr char kSimulatedLatencyHeader[] = "x-semnav-simulated-latency-s";

// The kSimulatedLatencyHeader value, if present and a sane number of seconds.
std::optional<absl::Duration> StatedLatency(const std::map<std::string, std::string>& headers);

// Vendor wire formats served over HTTP.
enum class BackendKind { kOpenAi, kAnthropic, kDashScope };

struct HttpBackendSpec {
  BackendKind kind = BackendKind::kOpenAi;
  std::string base_url;  // e.g. "https://api.openai.com/v1" (paths are appended)
  std::string model;
  int default_max_tokens = 1024;  // used when the request leaves max_tokens at 0
  bool require_key = true;        // false for local servers (Ollama, vLLM, llama.cpp)
};

class HttpBackend : public Backend {
 public:
  HttpBackend(HttpBackendSpec spec, ApiKey key, std::shared_ptr<HttpTransport> transport);

  absl::StatusOr<BackendReply> Complete(const CompletionRequest& request,
                                        absl::Time deadline) override;
  // Only OpenAI-compatible backends serve /embeddings.
  absl::StatusOr<EmbeddingReply> Embed(const EmbeddingRequest& request,
                                       absl::Time deadline) override;
  std::string model() const override { return spec_.model; }
  std::string endpoint() const override { return spec_.base_url; }
  bool configured() const override { return !spec_.require_key || !key_.empty(); }

 private:
  // POSTs and maps transport/HTTP errors; vendor text is redacted and truncated.
  absl::StatusOr<HttpResponse> PostForBody(const std::string& path, const std::string& body,
                                           absl::Time deadline);

  const HttpBackendSpec spec_;
  const ApiKey key_;
  const std::shared_ptr<HttpTransport> transport_;
  const std::unique_ptr<WireFormat> wire_;
};

}  // namespace semnav::modelproxy
