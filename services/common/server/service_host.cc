#include "services/common/server/service_host.h"

#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/health_check_service_interface.h>
#include <grpcpp/security/server_credentials.h>

#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/common/server/request_parse_interceptor.h"
#include "services/common/server/token_auth.h"

namespace semnav {
namespace {

absl::StatusOr<std::string> ReadPem(const std::string& path, absl::string_view key) {
  std::ifstream in(path);
  if (!in)
    return absl::NotFoundError(absl::StrCat("server.tls.", key, ": cannot read '", path, "'"));
  std::stringstream content;
  content << in.rdbuf();
  return content.str();
}

absl::StatusOr<std::shared_ptr<grpc::ServerCredentials>> MakeCredentials(
    const ServerOptions& options) {
  std::shared_ptr<grpc::ServerCredentials> credentials;
  if (options.tls.enabled()) {
    auto cert = ReadPem(options.tls.cert_file, "cert_file");
    if (!cert.ok()) return cert.status();
    auto key = ReadPem(options.tls.key_file, "key_file");
    if (!key.ok()) return key.status();
    grpc::SslServerCredentialsOptions ssl(GRPC_SSL_DONT_REQUEST_CLIENT_CERTIFICATE);
    ssl.pem_key_cert_pairs.push_back({*key, *cert});
    if (!options.tls.client_ca_file.empty()) {
      auto ca = ReadPem(options.tls.client_ca_file, "client_ca_file");
      if (!ca.ok()) return ca.status();
      ssl.pem_root_certs = *ca;
      ssl.client_certificate_request = GRPC_SSL_REQUEST_AND_REQUIRE_CLIENT_CERTIFICATE_AND_VERIFY;
    }
    credentials = grpc::SslServerCredentials(ssl);
  } else if (options.auth.enabled()) {
    // Insecure credentials cannot carry an auth processor; local credentials can, and they
    // admit loopback peers only, so a bearer token never crosses a network in the clear.
    credentials = grpc::experimental::LocalServerCredentials(LOCAL_TCP);
  } else {
    credentials = grpc::InsecureServerCredentials();
  }
  if (options.auth.enabled()) {
    absl::StatusOr<std::vector<std::string>> tokens = LoadTokens(options.auth);
    if (!tokens.ok()) {
      return absl::Status(tokens.status().code(),
                          absl::StrCat("server.auth: ", tokens.status().message()));
    }
    if (tokens->empty()) return absl::FailedPreconditionError("server.auth: no token configured");
    credentials->SetAuthMetadataProcessor(std::make_shared<TokenAuthProcessor>(*std::move(tokens)));
  }
  return credentials;
}

}  // namespace

ServiceHost::ServiceHost(std::string binary_name, ServerOptions options)
    : binary_name_(std::move(binary_name)),
      options_(std::move(options)),
      metrics_(std::make_shared<MetricsRegistry>()) {
  metrics_->set_server_name(binary_name_);
  metrics_service_ = std::make_unique<MetricsServiceImpl>(metrics_);
}

ServiceHost::~ServiceHost() { Shutdown(); }

void ServiceHost::AddService(std::unique_ptr<grpc::Service> service, std::string full_name) {
  services_.emplace_back(std::move(service), std::move(full_name));
}

void ServiceHost::OnShutdown(std::function<void()> hook) {
  shutdown_hooks_.push_back(std::move(hook));
}

absl::Status ServiceHost::Start() {
  absl::StatusOr<std::shared_ptr<grpc::ServerCredentials>> credentials = MakeCredentials(options_);
  if (!credentials.ok()) return credentials.status();

  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  builder.AddListeningPort(options_.listen, *credentials, &port_);
  // gRPC enables SO_REUSEPORT by default: a second server on the same port would start and split
  // the clients between two different maps. Binding must fail instead.
  builder.AddChannelArgument(GRPC_ARG_ALLOW_REUSEPORT, 0);
  builder.SetMaxReceiveMessageSize(options_.max_receive_message_mb * 1024 * 1024);
  builder.SetMaxSendMessageSize(options_.max_send_message_mb * 1024 * 1024);
  builder.AddChannelArgument(GRPC_ARG_KEEPALIVE_TIME_MS, options_.keepalive_time_s * 1000);
  builder.AddChannelArgument(GRPC_ARG_KEEPALIVE_TIMEOUT_MS, options_.keepalive_timeout_s * 1000);
  builder.AddChannelArgument(GRPC_ARG_KEEPALIVE_PERMIT_WITHOUT_CALLS, 1);
  builder.AddChannelArgument(GRPC_ARG_HTTP2_MIN_RECV_PING_INTERVAL_WITHOUT_DATA_MS, 5000);
  for (auto& [service, name] : services_) builder.RegisterService(service.get());
  builder.RegisterService(metrics_service_.get());
  std::vector<std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>> interceptors;
  // A body that does not parse is INVALID_ARGUMENT, not gRPC's bare UNIMPLEMENTED; first, so
  // the metrics see the status the client gets.
  interceptors.push_back(std::make_unique<RequestParseInterceptorFactory>());
  interceptors.push_back(std::make_unique<MetricsInterceptorFactory>(metrics_));
  builder.experimental().SetInterceptorCreators(std::move(interceptors));

  server_ = builder.BuildAndStart();
  if (!server_ || port_ == 0) {
    server_.reset();
    return absl::UnavailableError(
        absl::StrCat("server.listen: cannot bind '", options_.listen, "'"));
  }
  grpc::HealthCheckServiceInterface* health = server_->GetHealthCheckService();
  health->SetServingStatus("", true);
  for (const auto& [service, name] : services_) health->SetServingStatus(name, true);
  LogInfo("serving", {{"listen", options_.listen},
                      {"port", port_},
                      {"tls", options_.tls.enabled()},
                      {"mtls", !options_.tls.client_ca_file.empty()},
                      {"auth", options_.auth.enabled()}});
  return absl::OkStatus();
}

void ServiceHost::Shutdown() {
  if (!server_ || stopped_) return;
  stopped_ = true;
  server_->GetHealthCheckService()->Shutdown();  // every service NOT_SERVING from here on
  for (auto hook = shutdown_hooks_.rbegin(); hook != shutdown_hooks_.rend(); ++hook) (*hook)();
  server_->Shutdown(
      std::chrono::system_clock::now() +
      std::chrono::milliseconds(static_cast<int64_t>(options_.shutdown_grace_s * 1000)));
  server_->Wait();
  LogInfo("stopped");
}

}  // namespace semnav
