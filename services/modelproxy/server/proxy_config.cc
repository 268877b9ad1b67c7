#include "services/modelproxy/server/proxy_config.h"

#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/common/place_prior/place_prior.h"
#include "services/modelproxy/core/http_backend.h"
#include "services/modelproxy/core/offline/offline_backend.h"

namespace semnav::modelproxy {
namespace {

constexpr char kOfflineName[] = "offline";

BackendPolicy ReadPolicy(ConfigReader& r, BackendPolicy p) {
  double timeout_s = absl::ToDoubleSeconds(p.timeout);
  r.Read("timeout_s", &timeout_s).Read("max_in_flight", &p.max_in_flight);
  r.Check(timeout_s > 0, "timeout_s", "must be > 0");
  p.timeout = absl::Seconds(timeout_s);
  ConfigReader retry = r.Child("retry");
  double initial_ms = absl::ToDoubleMilliseconds(p.retry.initial_backoff);
  double max_ms = absl::ToDoubleMilliseconds(p.retry.max_backoff);
  retry.Read("max_attempts", &p.retry.max_attempts)
      .Read("initial_backoff_ms", &initial_ms)
      .Read("max_backoff_ms", &max_ms)
      .Read("multiplier", &p.retry.multiplier)
      .Read("jitter", &p.retry.jitter);
  retry.Check(initial_ms >= 0 && max_ms >= initial_ms, "max_backoff_ms",
              "must be >= initial_backoff_ms >= 0");
  p.retry.initial_backoff = absl::Milliseconds(initial_ms);
  p.retry.max_backoff = absl::Milliseconds(max_ms);
  ConfigReader breaker = r.Child("breaker");
  double open_s = absl::ToDoubleSeconds(p.breaker.open_duration);
  breaker.Read("failure_threshold", &p.breaker.failure_threshold).Read("open_s", &open_s);
  breaker.Check(open_s > 0, "open_s", "must be > 0");
  p.breaker.open_duration = absl::Seconds(open_s);
  return p;
}

// Reads every key first (so unknown-key checks see them all), then validates. Errors carry
// no path: the caller records them against the backend's key.
absl::StatusOr<BackendEntry> ReadHttpBackend(const std::string& name, ConfigReader& r,
                                             const std::shared_ptr<HttpTransport>& transport) {
  std::string kind = "openai", api_key_env, api_key_file;
  HttpBackendSpec spec;
  r.Read("kind", &kind)
      .Read("base_url", &spec.base_url)
      .Read("model", &spec.model)
      .Read("api_key_env", &api_key_env)
      .Read("api_key_file", &api_key_file)
      .Read("default_max_tokens", &spec.default_max_tokens);
  const BackendPolicy policy = ReadPolicy(r, BackendPolicy());
  if (kind == "openai") {
    spec.kind = BackendKind::kOpenAi;
  } else if (kind == "anthropic") {
    spec.kind = BackendKind::kAnthropic;
  } else if (kind == "dashscope") {
    spec.kind = BackendKind::kDashScope;
  } else {
    return absl::InvalidArgumentError(
        absl::StrCat("kind: '", kind, "' is not openai, anthropic or dashscope"));
  }
  if (spec.base_url.empty() || spec.model.empty()) {
    return absl::InvalidArgumentError("base_url and model are required");
  }
  if (!api_key_env.empty() && !api_key_file.empty()) {
    return absl::InvalidArgumentError("api_key_env and api_key_file are exclusive");
  }
  ApiKey key;
  if (!api_key_file.empty()) {
    absl::StatusOr<ApiKey> from_file = ApiKey::FromFile(api_key_file);
    if (!from_file.ok()) {
      return absl::Status(from_file.status().code(),
                          absl::StrCat("api_key_file: ", from_file.status().message()));
    }
    key = *std::move(from_file);
  } else if (!api_key_env.empty()) {
    key = ApiKey::FromEnv(api_key_env);
  }
  spec.require_key = !api_key_env.empty() || !api_key_file.empty();
  return BackendEntry{name, kind, std::make_unique<HttpBackend>(spec, std::move(key), transport),
                      policy};
}

absl::StatusOr<BackendEntry> ReadOfflineBackend(ConfigReader& r) {
  std::string data_dir = PlacePrior::DefaultDir();
  offline::OfflineParams params;
  r.Read("data_dir", &data_dir)
      .Read("min_score", &params.min_score)
      .Read("relatedness_weight", &params.relatedness_weight)
      .Read("place_weight", &params.place_weight);
  BackendPolicy policy;
  policy.timeout = absl::Seconds(5);
  policy.retry.max_attempts = 1;
  policy.max_in_flight = 64;
  policy = ReadPolicy(r, policy);
  absl::StatusOr<PlacePrior> prior = PlacePrior::Load(absl::StrCat(data_dir, "/", kPlacePriorFile));
  if (!prior.ok())
    return absl::Status(prior.status().code(),
                        absl::StrCat("data_dir: ", prior.status().message()));
  LogInfo(
      "offline_prior_loaded",
      {{"data_dir", data_dir}, {"objects", prior->object_count()}, {"edges", prior->edge_count()}});
  return BackendEntry{kOfflineName, "offline",
                      std::make_unique<offline::OfflineBackend>(*std::move(prior), params), policy};
}

// Records a failed step on `reader` (so every problem is reported at once, with its path).
void Record(ConfigReader& reader, const std::string& key, const absl::Status& status) {
  reader.Check(status.ok(), key, status.message());
}

}  // namespace

absl::StatusOr<BuiltProxy> BuildProxyFromConfig(ConfigReader& section, ProxyOptions options) {
  BuiltProxy built;
  double max_deadline_s = absl::ToDoubleSeconds(options.max_deadline);
  section.Read("default_alias", &options.default_alias)
      .Read("max_deadline_s", &max_deadline_s)
      .Read("worker_threads", &built.server.worker_threads);
  section.Check(max_deadline_s > 0, "max_deadline_s", "must be > 0");
  section.Check(built.server.worker_threads >= 1, "worker_threads", "must be >= 1");
  options.max_deadline = absl::Seconds(max_deadline_s);
  ConfigReader cache = section.Child("cache");
  double ttl_s = absl::ToDoubleSeconds(options.cache.ttl);
  cache.Read("capacity", &options.cache.capacity).Read("ttl_s", &ttl_s);
  cache.Check(options.cache.capacity >= 0, "capacity", "must be >= 0");
  options.cache.ttl = absl::Seconds(ttl_s);
  built.default_alias = options.default_alias;
  built.proxy = std::make_unique<ModelProxy>(options);

  ConfigReader offline_section = section.Child("offline");
  absl::StatusOr<BackendEntry> offline = ReadOfflineBackend(offline_section);
  if (!offline.ok()) {
    Record(section, "offline", offline.status());
  } else {
    Record(section, "offline", built.proxy->AddBackend(*std::move(offline)));
  }

  auto transport = std::make_shared<HttpTransport>();
  ConfigReader backends = section.Child("backends");
  for (const std::string& name : backends.Keys()) {
    ConfigReader backend = backends.Child(name);
    if (name == kOfflineName) {
      Record(backends, name,
             absl::InvalidArgumentError("the name is reserved; configure it under offline:"));
      continue;
    }
    absl::StatusOr<BackendEntry> entry = ReadHttpBackend(name, backend, transport);
    Record(backends, name,
           entry.ok() ? built.proxy->AddBackend(*std::move(entry)) : entry.status());
  }

  ConfigReader aliases = section.Child("aliases");
  const std::vector<std::string> alias_names = aliases.Keys();
  for (const std::string& alias : alias_names) {
    std::vector<std::string> chain;
    aliases.Read(alias, &chain);
    Record(aliases, alias, built.proxy->AddAlias(alias, chain));
  }
  if (alias_names.empty())
    Record(section, "aliases", built.proxy->AddAlias(options.default_alias, {kOfflineName}));
  section.Check(built.proxy->Aliases().count(options.default_alias) != 0, "default_alias",
                absl::StrCat("'", options.default_alias, "' is not one of aliases"));
  if (absl::Status s = section.Finish(); !s.ok()) return s;
  return built;
}

}  // namespace semnav::modelproxy
