#include "services/launcher/health_probe.h"

#include <grpcpp/client_context.h>
#include <netdb.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <iostream>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "grpc/health/v1/health.grpc.pb.h"
#include "services/common/net/host_port.h"

namespace semnav::launcher {

absl::StatusOr<std::string> ProbeHealth(const ClientOptions& client, const std::string& service,
                                        absl::Duration timeout) {
  absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = MakeChannel(client);
  if (!channel.ok()) return channel.status();
  auto stub = grpc::health::v1::Health::NewStub(*channel);
  grpc::ClientContext context;
  context.set_deadline(absl::ToChronoTime(absl::Now() + timeout));
  grpc::health::v1::HealthCheckRequest request;
  request.set_service(service);
  grpc::health::v1::HealthCheckResponse response;
  grpc::Status status = stub->Check(&context, request, &response);
  // grpc::StatusCode and absl::StatusCode share their numbering.
  if (!status.ok())
    return absl::Status(static_cast<absl::StatusCode>(status.error_code()), status.error_message());
  return grpc::health::v1::HealthCheckResponse::ServingStatus_Name(response.status());
}

absl::Status ProbeHttp(const std::string& url, absl::Duration timeout) {
  // A plain HTTP/1.0 GET over a socket: the service images carry `semnav` for health checks and
  // should not need libcurl for it. Only http://HOST:PORT/PATH is understood.
  constexpr absl::string_view kScheme = "http://";
  if (!absl::StartsWith(url, kScheme)) return absl::InvalidArgumentError("only http:// URLs");
  const std::string rest = url.substr(kScheme.size());
  const size_t slash = rest.find('/');
  const std::string authority = rest.substr(0, slash);
  const std::string path = slash == std::string::npos ? "/" : rest.substr(slash);
  const std::optional<HostPort> address = SplitHostPort(authority);
  if (!address) return absl::InvalidArgumentError("URL without a port");
  const std::string host = address->BareHost();
  addrinfo hints{};
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (::getaddrinfo(host.c_str(), address->port.c_str(), &hints, &found) != 0) {
    return absl::UnavailableError(absl::StrCat("cannot resolve ", host));
  }
  const int fd = ::socket(found->ai_family, found->ai_socktype, found->ai_protocol);
  timeval limit = absl::ToTimeval(timeout);
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof(limit));
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &limit, sizeof(limit));
  const bool connected = fd >= 0 && ::connect(fd, found->ai_addr, found->ai_addrlen) == 0;
  ::freeaddrinfo(found);
  if (!connected) {
    if (fd >= 0) ::close(fd);
    return absl::UnavailableError("connection refused");
  }
  const std::string request =
      absl::StrCat("GET ", path, " HTTP/1.0\r\nHost: ", authority, "\r\n\r\n");
  std::string reply;
  if (::send(fd, request.data(), request.size(), MSG_NOSIGNAL) ==
      static_cast<ssize_t>(request.size())) {
    char buffer[256];
    ssize_t n;
    while (reply.size() < 64 && (n = ::recv(fd, buffer, sizeof(buffer), 0)) > 0)
      reply.append(buffer, static_cast<size_t>(n));
  }
  ::close(fd);
  // "HTTP/1.1 200 OK"
  const size_t space = reply.find(' ');
  int status = 0;
  if (space == std::string::npos || !absl::SimpleAtoi(reply.substr(space + 1, 3), &status)) {
    return absl::UnavailableError("no HTTP answer");
  }
  if (status < 200 || status >= 300) return absl::UnavailableError(absl::StrCat("HTTP ", status));
  return absl::OkStatus();
}

const std::vector<FlagSpec>& ProbeFlags() {
  static const std::vector<FlagSpec> flags = {
      {"addr", "HOST:PORT", "the server to check (required)"},
      {"service", "NAME",
       "health service name, e.g. semnav.mapping.v1.MappingService (default: whole server)"},
      {"ca_file", "FILE", "PEM CA that signed the server certificate: TLS on"},
      {"cert_file", "FILE", "PEM client certificate for mTLS (with --key_file)"},
      {"key_file", "FILE", "PEM key of --cert_file"},
      {"server_name", "NAME", "name to verify in the server certificate (when --addr is an IP)"},
      {"token_file", "FILE", "bearer token file (mode 0600)"},
      {"token_env", "VAR", "environment variable holding the bearer token"},
      {"timeout_s", "SECONDS", "deadline of the check (default 3)"},
  };
  return flags;
}

std::string ProbeUsage() {
  return absl::StrCat("Usage: semnav probe --addr HOST:PORT [flags]\n\nFlags:\n",
                      FlagsHelp(ProbeFlags()));
}

int RunProbe(int argc, char** argv, int first) {
  absl::StatusOr<ParsedFlags> flags = ParseFlags(argc, argv, first, ProbeFlags());
  double timeout_s = 3;
  if (flags.ok() && flags->Has("timeout_s") &&
      !absl::SimpleAtod(*flags->Get("timeout_s"), &timeout_s)) {
    flags = absl::InvalidArgumentError("--timeout_s: not a number");
  }
  if (flags.ok() && !flags->positional.empty()) {
    flags = absl::InvalidArgumentError("unexpected argument '" + flags->positional.front() + "'");
  }
  if (flags.ok() && !flags->Has("addr")) flags = absl::InvalidArgumentError("--addr is required");
  if (!flags.ok()) {
    std::cerr << "semnav probe: " << flags.status().message() << "\n" << ProbeUsage();
    return 2;
  }
  ClientOptions client;
  client.address = *flags->Get("addr");
  client.ca_file = flags->Get("ca_file").value_or("");
  client.cert_file = flags->Get("cert_file").value_or("");
  client.key_file = flags->Get("key_file").value_or("");
  client.server_name = flags->Get("server_name").value_or("");
  client.token_file = flags->Get("token_file").value_or("");
  client.token_env = flags->Get("token_env").value_or("");
  absl::StatusOr<std::string> health =
      ProbeHealth(client, flags->Get("service").value_or(""), absl::Seconds(timeout_s));
  if (!health.ok()) {
    std::cerr << "semnav probe: " << absl::StatusCodeToString(health.status().code()) << ": "
              << health.status().message() << "\n";
    return 1;
  }
  std::cout << *health << "\n";
  return *health == "SERVING" ? 0 : 1;
}

}  // namespace semnav::launcher
