#include "services/modelproxy/core/http_backend.h"

#include "absl/status/status.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "services/common/status/retry_after.h"
#include "services/modelproxy/core/anthropic_wire.h"
#include "services/modelproxy/core/dashscope_wire.h"
#include "services/modelproxy/core/http_status.h"
#include "services/modelproxy/core/openai_wire.h"

namespace semnav::modelproxy {
namespace {

constexpr size_t kMaxVendorMessage = 200;

std::unique_ptr<WireFormat> MakeWire(BackendKind kind) {
  switch (kind) {
    case BackendKind::kAnthropic:
      return std::make_unique<AnthropicWire>();
    case BackendKind::kDashScope:
      return std::make_unique<DashScopeWire>();
    case BackendKind::kOpenAi:
      break;
  }
  return std::make_unique<OpenAiWire>();
}

}  // namespace

std::optional<absl::Duration> StatedLatency(const std::map<std::string, std::string>& headers) {
  auto it = headers.find(kSimulatedLatencyHeader);
  double seconds = 0.0;
  // Finite, non-negative and at most a day: anything else is ignored (the wall time stands).
  if (it == headers.end() || !absl::SimpleAtod(it->second, &seconds) || !(seconds >= 0.0) ||
      seconds > 86400.0) {
    return std::nullopt;
  }
  return absl::Seconds(seconds);
}

HttpBackend::HttpBackend(HttpBackendSpec spec, ApiKey key, std::shared_ptr<HttpTransport> transport)
    : spec_(std::move(spec)),
      key_(std::move(key)),
      transport_(std::move(transport)),
      wire_(MakeWire(spec_.kind)) {}

absl::StatusOr<HttpResponse> HttpBackend::PostForBody(const std::string& path,
                                                      const std::string& body,
                                                      absl::Time deadline) {
  if (!configured()) {
    return absl::FailedPreconditionError(absl::StrCat("no API key (", key_.source(), " is empty)"));
  }
  absl::StatusOr<HttpResponse> response =
      transport_->Post(spec_.base_url + path, wire_->Headers(key_.value()), body, deadline);
  if (!response.ok()) return response.status();
  if (response->status != 200) {
    std::string detail = key_.Redact(wire_->ErrorMessage(response->body));
    if (detail.size() > kMaxVendorMessage) detail = detail.substr(0, kMaxVendorMessage) + "...";
    absl::Status status = StatusFromHttp(response->status, detail);
    // A vendor that says when to come back (429, 503) is believed: the proxy's retry waits at
    // least that long, and the hint reaches the caller's back-off with the final error.
    if (auto it = response->headers.find("retry-after"); it != response->headers.end()) {
      if (std::optional<absl::Duration> after = ParseRetryAfterSeconds(it->second))
        SetRetryAfter(status, *after);
    }
    return status;
  }
  return response;
}

absl::StatusOr<BackendReply> HttpBackend::Complete(const CompletionRequest& request,
                                                   absl::Time deadline) {
  absl::StatusOr<HttpResponse> response =
      PostForBody(wire_->ChatPath(request),
                  wire_->ChatBody(request, spec_.model, spec_.default_max_tokens), deadline);
  if (!response.ok()) return response.status();
  absl::StatusOr<BackendReply> reply = wire_->ParseChat(response->body);
  if (!reply.ok()) return reply;
  if (reply->model.empty()) reply->model = spec_.model;
  reply->stated_latency = StatedLatency(response->headers);
  return reply;
}

absl::StatusOr<EmbeddingReply> HttpBackend::Embed(const EmbeddingRequest& request,
                                                  absl::Time deadline) {
  if (spec_.kind != BackendKind::kOpenAi) {
    return absl::UnimplementedError("only OpenAI-compatible backends serve /embeddings");
  }
  absl::StatusOr<HttpResponse> response = PostForBody(
      OpenAiWire::EmbeddingsPath(), OpenAiWire::EmbeddingsBody(request, spec_.model), deadline);
  if (!response.ok()) return response.status();
  absl::StatusOr<EmbeddingReply> reply =
      OpenAiWire::ParseEmbeddings(response->body, request.texts.size());
  if (!reply.ok()) return reply;
  if (reply->model.empty()) reply->model = spec_.model;
  reply->stated_latency = StatedLatency(response->headers);
  return reply;
}

}  // namespace semnav::modelproxy
