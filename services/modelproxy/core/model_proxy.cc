#include "services/modelproxy/core/model_proxy.h"

#include <algorithm>
#include <atomic>
#include <type_traits>

#include "absl/random/random.h"
#include "absl/status/status.h"
#include "absl/strings/cord.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/synchronization/mutex.h"
#include "services/common/status/field_error.h"
#include "services/common/status/retry_after.h"
#include "services/modelproxy/core/json_answer.h"
#include "services/modelproxy/core/request_key.h"
#include "services/modelproxy/core/request_validation.h"

namespace semnav::modelproxy {

struct ModelProxy::Managed {
  explicit Managed(BackendEntry e)
      : entry(std::move(e)), breaker(entry.policy.breaker), limiter(entry.policy.max_in_flight) {}

  BackendEntry entry;
  CircuitBreaker breaker;
  ConcurrencyLimiter limiter;
  std::atomic<int64_t> attempts{0};
  std::atomic<int64_t> failures{0};
  mutable absl::Mutex mu;
  std::string last_error ABSL_GUARDED_BY(mu);
};

template <typename Reply>
struct ModelProxy::ChainOutcome {
  absl::StatusOr<Reply> reply = absl::UnknownError("no attempt");
  std::string backend;
  std::vector<Attempt> attempts;
};

namespace {

// Failures that say the backend is down or broken (they feed the circuit breaker); other
// errors (bad request, auth, missing key) mean it answered and count as reachable.
bool IsOutage(const absl::Status& status) {
  return IsRetryable(status) || status.code() == absl::StatusCode::kDataLoss;
}

// Less time than this left counts as no time: no attempt starts, the call reports
// DEADLINE_EXCEEDED (transfers are cut at whole milliseconds).
constexpr absl::Duration kMinAttemptTime = absl::Milliseconds(1);

double UniformDraw() {
  thread_local absl::BitGen gen;
  return absl::Uniform(gen, 0.0, 1.0);
}

// A call outcome without a request field to blame, with a stable ErrorInfo reason.
absl::Status WithReason(absl::Status status, absl::string_view reason) {
  status.SetPayload(kReasonPayloadUrl, absl::Cord(reason));
  return status;
}

std::string Summary(const std::string& alias, const std::vector<Attempt>& attempts) {
  return absl::StrCat("model_alias '", alias,
                      "': ", absl::StrJoin(attempts, "; ", [](std::string* out, const Attempt& a) {
                        absl::StrAppend(out, a.backend, ": ",
                                        absl::StatusCodeToString(a.status.code()), ": ",
                                        a.status.message());
                      }));
}

absl::Status CheckPolicy(const BackendEntry& entry) {
  const BackendPolicy& p = entry.policy;
  const std::string where = absl::StrCat("backends.", entry.name, ".");
  if (p.timeout <= absl::ZeroDuration())
    return absl::InvalidArgumentError(where + "timeout_s must be > 0");
  if (p.retry.max_attempts < 1 || p.retry.max_attempts > 10) {
    return absl::InvalidArgumentError(where + "retry.max_attempts must be in [1, 10]");
  }
  if (p.retry.multiplier < 1.0)
    return absl::InvalidArgumentError(where + "retry.multiplier must be >= 1");
  if (p.retry.jitter < 0.0 || p.retry.jitter > 1.0) {
    return absl::InvalidArgumentError(where + "retry.jitter must be in [0, 1]");
  }
  if (p.breaker.failure_threshold < 1) {
    return absl::InvalidArgumentError(where + "breaker.failure_threshold must be >= 1");
  }
  if (p.max_in_flight < 1) return absl::InvalidArgumentError(where + "max_in_flight must be >= 1");
  return absl::OkStatus();
}

}  // namespace

ModelProxy::ModelProxy(ProxyOptions options)
    : options_(std::move(options)), cache_(options_.cache) {}
ModelProxy::~ModelProxy() = default;

absl::Status ModelProxy::AddBackend(BackendEntry entry) {
  if (entry.name.empty() || entry.backend == nullptr) {
    return absl::InvalidArgumentError("backends: every backend needs a name");
  }
  if (backends_.count(entry.name) != 0) {
    return absl::InvalidArgumentError(absl::StrCat("backends.", entry.name, " is defined twice"));
  }
  if (absl::Status s = CheckPolicy(entry); !s.ok()) return s;
  const std::string name = entry.name;
  backends_.emplace(name, std::make_unique<Managed>(std::move(entry)));
  return absl::OkStatus();
}

absl::Status ModelProxy::AddAlias(const std::string& alias, const std::vector<std::string>& chain) {
  if (alias.empty() || aliases_.count(alias) != 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("aliases: '", alias, "' is empty or defined twice"));
  }
  if (chain.empty())
    return absl::InvalidArgumentError(absl::StrCat("aliases.", alias, " has an empty chain"));
  for (const std::string& name : chain) {
    if (backends_.count(name) == 0) {
      return absl::NotFoundError(
          absl::StrCat("aliases.", alias, " names unknown backend '", name, "'"));
    }
  }
  aliases_[alias] = chain;
  return absl::OkStatus();
}

absl::StatusOr<std::vector<ModelProxy::Managed*>> ModelProxy::Chain(
    const std::string& alias) const {
  auto it = aliases_.find(alias);
  if (it == aliases_.end()) {
    return FieldStatus(absl::StatusCode::kNotFound, "model_alias",
                       absl::StrCat("'", Preview(alias), "' is not configured"), "ALIAS_NOT_FOUND");
  }
  std::vector<Managed*> chain;
  for (const std::string& name : it->second) chain.push_back(backends_.at(name).get());
  return chain;
}

template <typename Reply>
ModelProxy::ChainOutcome<Reply> ModelProxy::RunChain(
    const std::string& alias, const std::vector<Managed*>& chain, absl::Time deadline,
    const std::function<absl::StatusOr<Reply>(Backend&, absl::Time)>& call) {
  ChainOutcome<Reply> out;
  auto fail = [&](Managed& m, absl::Status status, absl::Duration latency) {
    Attempt attempt{m.entry.name, std::move(status), latency};
    if (options_.on_failed_attempt) options_.on_failed_attempt(alias, attempt);
    out.attempts.push_back(std::move(attempt));
  };
  for (Managed* m : chain) {
    const BackendPolicy& policy = m->entry.policy;
    if (m->breaker.state(absl::Now()) == BreakerState::kOpen) {
      fail(*m, absl::UnavailableError("circuit open"), absl::ZeroDuration());
      continue;
    }
    const absl::Time queue_start = absl::Now();
    std::optional<ConcurrencyLimiter::Permit> permit =
        m->limiter.Acquire(std::min(deadline, queue_start + policy.timeout));
    if (!permit) {
      fail(*m, absl::ResourceExhaustedError("concurrency limit: no free slot in time"),
           absl::Now() - queue_start);
      continue;
    }
    for (int attempt = 0; attempt < policy.retry.max_attempts; ++attempt) {
      const absl::Time start = absl::Now();
      if (start + kMinAttemptTime >= deadline) break;
      if (!m->breaker.Allow(start)) {
        if (attempt == 0) fail(*m, absl::UnavailableError("circuit open"), absl::ZeroDuration());
        break;
      }
      absl::StatusOr<Reply> reply =
          call(*m->entry.backend, std::min(deadline, start + policy.timeout));
      const absl::Duration latency = absl::Now() - start;
      ++m->attempts;
      if (reply.ok()) {
        m->breaker.RecordSuccess();
        const absl::Duration reported = reply->stated_latency.value_or(latency);
        out.attempts.push_back(Attempt{m->entry.name, absl::OkStatus(), reported});
        out.reply = std::move(reply);
        out.backend = m->entry.name;
        return out;
      }
      ++m->failures;
      {
        absl::MutexLock lock(&m->mu);
        m->last_error = absl::StrCat(absl::StatusCodeToString(reply.status().code()), ": ",
                                     reply.status().message());
      }
      if (IsOutage(reply.status())) {
        m->breaker.RecordFailure(absl::Now());
      } else {
        m->breaker.RecordSuccess();
      }
      const bool retry = IsRetryable(reply.status());
      fail(*m, reply.status(), latency);
      if (!retry) break;
      // The vendor's Retry-After, when it sent one, is the least wait before asking it again.
      const absl::Duration backoff =
          std::max(policy.retry.Backoff(attempt, UniformDraw()),
                   RetryAfter(reply.status()).value_or(absl::ZeroDuration()));
      if (attempt + 1 >= policy.retry.max_attempts ||
          absl::Now() + backoff + kMinAttemptTime >= deadline)
        break;
      absl::SleepFor(backoff);
    }
  }
  if (absl::Now() + kMinAttemptTime >= deadline) {
    out.reply = WithReason(absl::DeadlineExceededError(
                               absl::StrCat("deadline passed; ", Summary(alias, out.attempts))),
                           "DEADLINE_EXCEEDED");
  } else if (!out.attempts.empty() &&
             out.attempts.back().status.code() == absl::StatusCode::kInvalidArgument) {
    // The request was valid here but every backend refused it (e.g. too long for its model).
    out.reply =
        WithReason(absl::InvalidArgumentError(Summary(alias, out.attempts)), "BACKEND_REJECTED");
  } else {
    out.reply = WithReason(
        absl::UnavailableError(absl::StrCat("no backend answered; ", Summary(alias, out.attempts))),
        "BACKEND_UNAVAILABLE");
  }
  // The longest Retry-After any backend asked for goes back to the caller with the error.
  std::optional<absl::Duration> retry_after;
  for (const Attempt& attempt : out.attempts) {
    if (const std::optional<absl::Duration> after = RetryAfter(attempt.status))
      retry_after = std::max(retry_after.value_or(absl::ZeroDuration()), *after);
  }
  if (retry_after.has_value()) {
    absl::Status failed = out.reply.status();
    SetRetryAfter(failed, *retry_after);
    out.reply = std::move(failed);
  }
  return out;
}

absl::StatusOr<std::vector<ModelProxy::Managed*>> ModelProxy::Begin(const absl::Status& validation,
                                                                    const std::string& alias,
                                                                    absl::Time start,
                                                                    absl::Time& deadline) const {
  if (!validation.ok()) return validation;
  absl::StatusOr<std::vector<Managed*>> chain = Chain(alias);
  if (!chain.ok()) return chain.status();
  deadline = std::min(deadline, start + options_.max_deadline);
  if (start >= deadline) {
    return WithReason(absl::DeadlineExceededError("deadline passed before the call started"),
                      "DEADLINE_EXCEEDED");
  }
  return chain;
}

absl::StatusOr<CompletionResult> ModelProxy::Complete(CompletionRequest request,
                                                      const CallerId& caller, absl::Time deadline) {
  const absl::Time start = absl::Now();
  if (request.alias.empty()) request.alias = options_.default_alias;
  absl::StatusOr<std::vector<Managed*>> chain =
      Begin(ValidateCompletionRequest(request), request.alias, start, deadline);
  if (!chain.ok()) return chain.status();

  const bool want_json = request.format != ResponseFormat::kText;
  const std::string key = RequestKey(request);
  CompletionResult result;
  if (!request.bypass_cache) {
    if (std::optional<CachedAnswer> hit = cache_.Get(key, start)) {
      result.reply = std::move(hit->reply);
      result.backend = std::move(hit->backend);
      result.cached = true;
    }
  }
  if (!result.cached) {
    ChainOutcome<BackendReply> outcome = RunChain<BackendReply>(
        request.alias, *chain, deadline,
        [&](Backend& backend, absl::Time attempt_deadline) -> absl::StatusOr<BackendReply> {
          absl::StatusOr<BackendReply> reply = backend.Complete(request, attempt_deadline);
          if (reply.ok() && want_json) {
            if (absl::Status s = ParseJsonAnswer(reply->text).status(); !s.ok()) return s;
          }
          return reply;
        });
    if (!outcome.reply.ok()) {
      usage_.RecordFailure(caller);
      return outcome.reply.status();
    }
    result.reply = std::move(*outcome.reply);
    result.backend = std::move(outcome.backend);
    result.attempts = std::move(outcome.attempts);
    cache_.Put(key, CachedAnswer{result.reply, result.backend}, absl::Now());
  }
  if (want_json) result.json = ParseJsonAnswer(result.reply.text)->dump();
  usage_.RecordAnswer(caller, result.backend, result.reply.usage, result.cached);
  result.latency = absl::Now() - start;
  // A simulated backend's answer takes the time it states (simulated); a cache hit is immediate.
  if (!result.cached && result.reply.stated_latency.has_value())
    result.latency = *result.reply.stated_latency;
  return result;
}

absl::StatusOr<EmbeddingResult> ModelProxy::Embed(EmbeddingRequest request, const CallerId& caller,
                                                  absl::Time deadline) {
  const absl::Time start = absl::Now();
  if (request.alias.empty()) request.alias = options_.default_alias;
  absl::StatusOr<std::vector<Managed*>> chain =
      Begin(ValidateEmbeddingRequest(request), request.alias, start, deadline);
  if (!chain.ok()) return chain.status();

  ChainOutcome<EmbeddingReply> outcome = RunChain<EmbeddingReply>(
      request.alias, *chain, deadline, [&](Backend& backend, absl::Time attempt_deadline) {
        return backend.Embed(request, attempt_deadline);
      });
  if (!outcome.reply.ok()) {
    usage_.RecordFailure(caller);
    return outcome.reply.status();
  }
  EmbeddingResult result;
  result.reply = std::move(*outcome.reply);
  result.backend = std::move(outcome.backend);
  result.attempts = std::move(outcome.attempts);
  usage_.RecordAnswer(caller, result.backend, result.reply.usage, /*cached=*/false);
  result.latency = result.reply.stated_latency.value_or(absl::Now() - start);
  return result;
}

std::vector<BackendStatus> ModelProxy::ListBackends(absl::Time now) const {
  std::vector<BackendStatus> out;
  for (const auto& [name, m] : backends_) {
    BackendStatus s;
    s.name = name;
    s.kind = m->entry.kind;
    s.model = m->entry.backend->model();
    s.endpoint = m->entry.backend->endpoint();
    s.configured = m->entry.backend->configured();
    s.breaker = m->breaker.state(now);
    s.consecutive_failures = m->breaker.consecutive_failures();
    s.in_flight = m->limiter.in_flight();
    s.max_in_flight = m->limiter.max_in_flight();
    s.attempts = m->attempts.load();
    s.failures = m->failures.load();
    absl::MutexLock lock(&m->mu);
    s.last_error = m->last_error;
    out.push_back(std::move(s));
  }
  return out;
}

std::map<std::string, std::vector<std::string>> ModelProxy::Aliases() const { return aliases_; }

}  // namespace semnav::modelproxy
