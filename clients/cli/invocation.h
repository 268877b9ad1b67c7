// One semnavctl command line after parsing: which service addresses, TLS and token to use, the
// call deadline and the output format, shared by every command.
#pragma once

#include <grpcpp/channel.h>
#include <grpcpp/client_context.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "services/common/cli/flags.h"

namespace semnav::cli {

enum class Service { kGateway, kMapping, kPlanning, kRelocalization, kModelProxy };

struct ServiceInfo {
  Service service;
  std::string name;             // "gateway"
  std::string address_flag;     // "gateway-addr"
  std::string default_address;  // deploy/local.yaml
};
const std::vector<ServiceInfo>& AllServices();
const ServiceInfo& InfoOf(Service service);

// Flags every command takes (--addr, --<service>-addr, TLS, token, --deadline, --json).
const std::vector<FlagSpec>& ConnectionFlags();

class Invocation {
 public:
  // Parses argv[first..) against `command_flags` plus ConnectionFlags(). `primary` is the service
  // that --addr names.
  static absl::StatusOr<Invocation> Parse(int argc, char** argv, int first,
                                          const std::vector<FlagSpec>& command_flags,
                                          Service primary);

  const ParsedFlags& flags() const { return flags_; }
  const std::vector<std::string>& positional() const { return flags_.positional; }
  std::string Flag(const std::string& name, const std::string& fallback = "") const;
  bool Has(const std::string& name) const { return flags_.Has(name); }
  bool json() const { return flags_.Has("json"); }

  std::string Address(Service service) const;
  absl::StatusOr<std::shared_ptr<grpc::Channel>> Channel(Service service) const;
  // Applies --deadline (or `fallback` when unset; nullopt = no deadline) to a call.
  void SetDeadline(grpc::ClientContext& context, std::optional<absl::Duration> fallback) const;
  // --request-id, or a fresh random id for this call.
  std::string RequestId() const;

 private:
  ParsedFlags flags_;
  Service primary_ = Service::kGateway;
  std::optional<absl::Duration> deadline_;
};

// Default deadline of unary calls when --deadline is not given.
inline constexpr absl::Duration kDefaultUnaryDeadline = absl::Seconds(10);

}  // namespace semnav::cli
