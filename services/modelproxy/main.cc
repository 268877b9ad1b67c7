// semnav-model-proxy: the cloud model proxy (LLM/VLM backends, fallback, cache, accounting)
// with the offline ConceptNet prior as its key-free default.
#include <memory>

#include "services/common/logging/log.h"
#include "services/common/server/service_binary.h"
#include "services/modelproxy/server/model_proxy_service.h"
#include "services/modelproxy/server/proxy_config.h"

namespace {

absl::Status Setup(semnav::ConfigReader& section, semnav::ServiceHost& host) {
  semnav::modelproxy::ProxyOptions options;
  options.on_failed_attempt = [](const std::string& alias,
                                 const semnav::modelproxy::Attempt& attempt) {
    // Attempt statuses are redacted of keys by the backends.
    semnav::LogWarning("model_attempt_failed",
                       {{"alias", alias},
                        {"backend", attempt.backend},
                        {"code", absl::StatusCodeToString(attempt.status.code())},
                        {"message", attempt.status.message()},
                        {"latency_ms", absl::ToDoubleMilliseconds(attempt.latency)}});
  };
  absl::StatusOr<semnav::modelproxy::BuiltProxy> built =
      semnav::modelproxy::BuildProxyFromConfig(section, std::move(options));
  if (!built.ok()) return built.status();
  auto service = std::make_unique<semnav::modelproxy::ModelProxyServiceImpl>(
      std::move(built->proxy), built->default_alias, built->server.worker_threads);
  semnav::modelproxy::ModelProxyServiceImpl* raw = service.get();
  host.OnShutdown([raw] { raw->Shutdown(); });
  host.AddService(std::move(service), "semnav.modelproxy.v1.ModelProxyService");
  return absl::OkStatus();
}

}  // namespace

int main(int argc, char** argv) {
  return semnav::RunServiceBinary(
      argc, argv,
      {"semnav-model-proxy",
       "LLM/VLM proxy: fallback chains, deadlines, cache, usage, offline prior", "127.0.0.1:50054",
       "modelproxy", Setup});
}
