#include "services/launcher/health_probe.h"

#include <iostream>

#include <curl/curl.h>
#include <grpcpp/client_context.h>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "grpc/health/v1/health.grpc.pb.h"

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
  if (!status.ok()) return absl::Status(static_cast<absl::StatusCode>(status.error_code()), status.error_message());
  return grpc::health::v1::HealthCheckResponse::ServingStatus_Name(response.status());
}

absl::Status ProbeHttp(const std::string& url, absl::Duration timeout) {
  CURL* curl = curl_easy_init();
  if (curl == nullptr) return absl::InternalError("curl_easy_init failed");
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, static_cast<long>(absl::ToInt64Milliseconds(timeout)));
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, +[](char*, size_t size, size_t count, void*) { return size * count; });
  const CURLcode code = curl_easy_perform(curl);
  long http_status = 0;
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &http_status);
  curl_easy_cleanup(curl);
  if (code != CURLE_OK) return absl::UnavailableError(curl_easy_strerror(code));
  if (http_status < 200 || http_status >= 300) return absl::UnavailableError(absl::StrCat("HTTP ", http_status));
  return absl::OkStatus();
}

const std::vector<FlagSpec>& ProbeFlags() {
  static const std::vector<FlagSpec> flags = {
      {"addr", "HOST:PORT", "the server to check (required)"},
      {"service", "NAME", "health service name, e.g. semnav.mapping.v1.MappingService (default: whole server)"},
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
  if (flags.ok() && flags->Has("timeout_s") && !absl::SimpleAtod(*flags->Get("timeout_s"), &timeout_s)) {
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
