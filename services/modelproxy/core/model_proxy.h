#pragma once
// The proxy: named backends behind aliases, each alias an ordered fallback chain. Per call:
// validate, consult the cache, then walk the chain; every attempt ends inside the caller's
// deadline; transient failures are retried with backoff while time remains; each backend has a
// circuit breaker and a concurrency limit; malformed answers fall through to the next backend.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "services/modelproxy/core/backend.h"
#include "services/modelproxy/core/circuit_breaker.h"
#include "services/modelproxy/core/concurrency_limiter.h"
#include "services/modelproxy/core/request.h"
#include "services/modelproxy/core/response_cache.h"
#include "services/modelproxy/core/retry_policy.h"
#include "services/modelproxy/core/usage_ledger.h"

namespace semnav::modelproxy {

struct BackendPolicy {
  absl::Duration timeout = absl::Seconds(30);  // cap per attempt (the caller's deadline also caps)
  RetryPolicy retry;
  BreakerPolicy breaker;
  int max_in_flight = 16;  // concurrent calls to this backend (>= 1)
};

struct BackendEntry {
  std::string name;
  std::string kind;  // "openai", "anthropic", "dashscope", "offline" (for listings)
  std::unique_ptr<Backend> backend;
  BackendPolicy policy;
};

// One try at one backend, as reported back to the caller (and logged).
struct Attempt {
  std::string backend;
  absl::Status status;  // OK for the answering attempt; vendor text already redacted
  absl::Duration latency;
};

struct CompletionResult {
  BackendReply reply;
  std::string backend;  // backend name that answered (original one for cache hits)
  std::string json;     // compact JSON of the answer when a JSON format was asked, else ""
  bool cached = false;
  absl::Duration latency;
  std::vector<Attempt> attempts;
};

struct EmbeddingResult {
  EmbeddingReply reply;
  std::string backend;
  absl::Duration latency;
  std::vector<Attempt> attempts;
};

struct BackendStatus {
  std::string name;
  std::string kind;
  std::string model;
  std::string endpoint;
  bool configured = false;
  BreakerState breaker = BreakerState::kClosed;
  int consecutive_failures = 0;
  int in_flight = 0;
  int max_in_flight = 0;
  int64_t attempts = 0;
  int64_t failures = 0;
  std::string last_error;  // "" if none
};

struct ProxyOptions {
  std::string default_alias = "default";  // used when a request names no alias
  CachePolicy cache;
  absl::Duration max_deadline = absl::Seconds(120);  // cap on any caller deadline
  // Called for every failed attempt (for logs). Statuses carry no keys.
  std::function<void(const std::string& alias, const Attempt&)> on_failed_attempt;
};

class ModelProxy {
 public:
  explicit ModelProxy(ProxyOptions options);
  ~ModelProxy();

  // INVALID_ARGUMENT for an empty or repeated name, or a policy out of range.
  absl::Status AddBackend(BackendEntry entry);
  // NOT_FOUND naming an unknown backend; INVALID_ARGUMENT for an empty/repeated alias or chain.
  absl::Status AddAlias(const std::string& alias, const std::vector<std::string>& chain);

  // INVALID_ARGUMENT (bad request, field named), NOT_FOUND (model_alias), DEADLINE_EXCEEDED
  // (deadline passed; attempts listed), UNAVAILABLE (every backend failed; attempts listed).
  absl::StatusOr<CompletionResult> Complete(CompletionRequest request, const CallerId& caller,
                                            absl::Time deadline);
  absl::StatusOr<EmbeddingResult> Embed(EmbeddingRequest request, const CallerId& caller,
                                        absl::Time deadline);

  std::vector<BackendStatus> ListBackends(absl::Time now) const;
  std::map<std::string, std::vector<std::string>> Aliases() const;
  const UsageLedger& usage() const { return usage_; }
  int cache_entries() const { return cache_.size(); }

 private:
  struct Managed;
  template <typename Reply>
  struct ChainOutcome;

  absl::StatusOr<std::vector<Managed*>> Chain(const std::string& alias) const;
  // Shared start of a call: the validation result, the alias's chain, and `deadline` capped by
  // max_deadline (DEADLINE_EXCEEDED if already past).
  absl::StatusOr<std::vector<Managed*>> Begin(const absl::Status& validation,
                                              const std::string& alias, absl::Time start,
                                              absl::Time& deadline) const;
  template <typename Reply>
  ChainOutcome<Reply> RunChain(
      const std::string& alias, const std::vector<Managed*>& chain, absl::Time deadline,
      const std::function<absl::StatusOr<Reply>(Backend&, absl::Time)>& call);

  const ProxyOptions options_;
  ResponseCache cache_;
  UsageLedger usage_;
  std::map<std::string, std::unique_ptr<Managed>> backends_;
  std::map<std::string, std::vector<std::string>> aliases_;
};

}  // namespace semnav::modelproxy
