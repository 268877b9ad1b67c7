#pragma once

#include <grpcpp/server.h>
#include <grpcpp/server_builder.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "services/common/server/metrics.h"
#include "services/common/server/server_options.h"

namespace semnav {

// Runs one gRPC server with what every semnav binary needs: the callback API, grpc.health.v1
// with per-service status, reflection, the metrics service, keepalive, message limits,
// optional TLS/mTLS and bearer-token auth, and a graceful shutdown.
class ServiceHost {
 public:
  ServiceHost(std::string binary_name, ServerOptions options);
  ~ServiceHost();
  ServiceHost(const ServiceHost&) = delete;
  ServiceHost& operator=(const ServiceHost&) = delete;

  // Registers (and owns) a service; `full_name` (e.g. "semnav.mapping.v1.MappingService")
  // is the name its health status is reported under. Call before Start().
  void AddService(std::unique_ptr<grpc::Service> service, std::string full_name);
  // Runs before the server stops accepting calls, in reverse order of registration
  // (finish long-lived streams, stop background threads).
  void OnShutdown(std::function<void()> hook);

  // Binds and starts; health becomes SERVING for "" and every added service.
  absl::Status Start();
  // The bound port (after Start()).
  int port() const { return port_; }
  // Health NOT_SERVING, shutdown hooks, then Shutdown with the grace deadline. Idempotent.
  void Shutdown();

  const std::string& binary_name() const { return binary_name_; }
  MetricsRegistry& metrics() { return *metrics_; }

 private:
  std::string binary_name_;
  ServerOptions options_;
  std::vector<std::pair<std::unique_ptr<grpc::Service>, std::string>> services_;
  std::vector<std::function<void()>> shutdown_hooks_;
  std::shared_ptr<MetricsRegistry> metrics_;
  std::unique_ptr<MetricsServiceImpl> metrics_service_;
  std::unique_ptr<grpc::Server> server_;
  int port_ = 0;
  bool stopped_ = false;
};

}  // namespace semnav
