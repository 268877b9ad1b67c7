#pragma once
// One model backend: a remote vendor API or the embedded offline prior. Implementations are
// thread-safe; the proxy adds retries, circuit breaking and concurrency limits around them.
#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "services/modelproxy/core/request.h"

namespace semnav::modelproxy {

class Backend {
 public:
  virtual ~Backend() = default;
  // One attempt that must end by `deadline`. Errors use the codes IsRetryable() knows.
  virtual absl::StatusOr<BackendReply> Complete(const CompletionRequest& request,
                                                absl::Time deadline) = 0;
  // UNIMPLEMENTED when the backend has no text encoder.
  virtual absl::StatusOr<EmbeddingReply> Embed(const EmbeddingRequest& request,
                                               absl::Time deadline) = 0;
  // Model name reported in listings.
  virtual std::string model() const = 0;
  // Base URL for listings ("" for embedded backends); never contains a key.
  virtual std::string endpoint() const = 0;
  // False when a required key is missing.
  virtual bool configured() const = 0;
};

}  // namespace semnav::modelproxy
