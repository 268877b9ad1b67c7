#include "clients/cli/invocation.h"

#include <chrono>
#include <cstdlib>
#include <random>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "clients/cli/core/args.h"
#include "services/common/client/channel.h"

namespace semnav::cli {

const std::vector<ServiceInfo>& AllServices() {
  static const std::vector<ServiceInfo> services = {
      {Service::kGateway, "gateway", "gateway-addr", "127.0.0.1:50050"},
      {Service::kMapping, "mapping", "mapping-addr", "127.0.0.1:50051"},
      {Service::kPlanning, "planning", "planning-addr", "127.0.0.1:50052"},
      {Service::kRelocalization, "relocalization", "relocalization-addr", "127.0.0.1:50053"},
      {Service::kModelProxy, "modelproxy", "modelproxy-addr", "127.0.0.1:50054"},
  };
  return services;
}

const ServiceInfo& InfoOf(Service service) {
  for (const ServiceInfo& info : AllServices()) {
    if (info.service == service) return info;
  }
  return AllServices().front();
}

const std::vector<FlagSpec>& ConnectionFlags() {
  static const std::vector<FlagSpec> flags = [] {
    std::vector<FlagSpec> specs = {
        {"addr", "HOST:PORT", "address of the service this command talks to"}};
    for (const ServiceInfo& info : AllServices()) {
      specs.push_back({info.address_flag, "HOST:PORT",
                       absl::StrCat(info.name, " address (", info.default_address, ")")});
    }
    specs.insert(specs.end(),
                 {
                     {"tls-ca", "FILE", "PEM CA to verify the servers (enables TLS)"},
                     {"tls-cert", "FILE", "PEM client certificate for mTLS (with --tls-key)"},
                     {"tls-key", "FILE", "PEM client key for mTLS"},
                     {"tls-server-name", "NAME", "expected server name when addresses are IPs"},
                     {"token-file", "FILE", "bearer token from a 0600 file"},
                     {"token-env", "VAR",
                      "bearer token from an environment variable (default SEMNAV_TOKEN when set)"},
                     {"deadline", "SECONDS",
                      "give up after this long (unary calls default 10 s; streams wait)"},
                     {"json", "", "machine-readable JSON output (one object per line for streams)"},
                 });
    return specs;
  }();
  return flags;
}

absl::StatusOr<Invocation> Invocation::Parse(int argc, char** argv, int first,
                                             const std::vector<FlagSpec>& command_flags,
                                             Service primary) {
  std::vector<FlagSpec> specs = command_flags;
  specs.insert(specs.end(), ConnectionFlags().begin(), ConnectionFlags().end());
  absl::StatusOr<ParsedFlags> flags = ParseFlags(argc, argv, first, specs);
  if (!flags.ok()) return flags.status();
  Invocation invocation;
  invocation.flags_ = *std::move(flags);
  invocation.primary_ = primary;
  if (auto deadline = invocation.flags_.Get("deadline")) {
    absl::StatusOr<absl::Duration> parsed = ParseSeconds("deadline", *deadline);
    if (!parsed.ok()) return parsed.status();
    invocation.deadline_ = *parsed;
  }
  if (invocation.Has("tls-cert") != invocation.Has("tls-key")) {
    return absl::InvalidArgumentError("--tls-cert and --tls-key must be given together");
  }
  if ((invocation.Has("tls-cert") || invocation.Has("tls-server-name")) &&
      !invocation.Has("tls-ca")) {
    return absl::InvalidArgumentError("--tls-cert and --tls-server-name need --tls-ca");
  }
  return invocation;
}

std::string Invocation::Flag(const std::string& name, const std::string& fallback) const {
  return flags_.Get(name).value_or(fallback);
}

std::string Invocation::Address(Service service) const {
  const ServiceInfo& info = InfoOf(service);
  if (service == primary_ && Has("addr")) return Flag("addr");
  return Flag(info.address_flag, info.default_address);
}

absl::StatusOr<std::shared_ptr<grpc::Channel>> Invocation::Channel(Service service) const {
  ClientOptions options;
  options.address = Address(service);
  options.ca_file = Flag("tls-ca");
  options.cert_file = Flag("tls-cert");
  options.key_file = Flag("tls-key");
  options.server_name = Flag("tls-server-name");
  options.token_file = Flag("token-file");
  options.token_env = Flag("token-env");
  if (options.token_file.empty() && options.token_env.empty() &&
      std::getenv("SEMNAV_TOKEN") != nullptr) {
    options.token_env = "SEMNAV_TOKEN";
  }
  return MakeChannel(options);
}

void Invocation::SetDeadline(grpc::ClientContext& context,
                             std::optional<absl::Duration> fallback) const {
  const std::optional<absl::Duration> deadline = deadline_ ? deadline_ : fallback;
  if (deadline)
    context.set_deadline(std::chrono::system_clock::now() + absl::ToChronoNanoseconds(*deadline));
}

std::string Invocation::RequestId() const {
  if (Has("request-id")) return Flag("request-id");
  std::random_device random;
  return absl::StrFormat("semnavctl-%08x%08x", random(), random());
}

}  // namespace semnav::cli
