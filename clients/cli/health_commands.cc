// health: grpc.health.v1 of every service (or one), as a table.
#include <iostream>
#include <nlohmann/json.hpp>

#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "clients/cli/core/exit_codes.h"
#include "clients/cli/core/table.h"
#include "grpc/health/v1/health.grpc.pb.h"

namespace semnav::cli {
namespace {

using HealthStub = grpc::health::v1::Health::Stub;

struct Probe {
  std::string address;
  absl::Status call;   // the Check call itself
  std::string status;  // SERVING, NOT_SERVING, ... or the call's error code
};

Probe Check(const Invocation& invocation, const ServiceInfo& info,
            const std::shared_ptr<grpc::Channel>& channel) {
  Probe probe{invocation.Address(info.service), absl::OkStatus(), ""};
  std::unique_ptr<HealthStub> stub = grpc::health::v1::Health::NewStub(channel);
  grpc::health::v1::HealthCheckResponse response;
  probe.call = CallUnary(invocation, *stub, &HealthStub::Check,
                         grpc::health::v1::HealthCheckRequest(), &response);
  probe.status = probe.call.ok()
                     ? grpc::health::v1::HealthCheckResponse::ServingStatus_Name(response.status())
                     : absl::StatusCodeToString(probe.call.code());
  return probe;
}

int Health(const Invocation& invocation) {
  std::vector<const ServiceInfo*> selected;
  for (const ServiceInfo& info : AllServices()) {
    if (!invocation.Has("service") || invocation.Flag("service") == info.name)
      selected.push_back(&info);
  }
  if (selected.empty())
    return UsageError("--service: no service named '" + invocation.Flag("service") + "'");
  ExitCode exit = ExitCode::kOk;
  Table table({"SERVICE", "ADDRESS", "STATUS"});
  nlohmann::json services = nlohmann::json::array();
  for (const ServiceInfo* info : selected) {
    // A channel that cannot be made (unreadable TLS file, missing token) is a usage error.
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = invocation.Channel(info->service);
    if (!channel.ok()) return UsageError(std::string(channel.status().message()));
    const Probe probe = Check(invocation, *info, *channel);
    table.AddRow({info->name, probe.address, probe.status});
    services.push_back(
        {{"service", info->name}, {"address", probe.address}, {"status", probe.status}});
    if (exit != ExitCode::kOk) continue;
    if (!probe.call.ok()) {
      exit = ExitCodeFor(probe.call.code());
    } else if (probe.status != "SERVING") {
      exit = ExitCode::kUnavailable;
    }
  }
  if (invocation.json()) {
    std::cout
        << nlohmann::json{{"services", services}, {"all_serving", exit == ExitCode::kOk}}.dump()
        << std::endl;
  } else {
    std::cout << table.Render();
  }
  return ToInt(exit);
}

}  // namespace

std::vector<Command> HealthCommands() {
  return {
      {"health",
       "",
       "",
       "grpc.health.v1 status of every service (exit 3 when one is not SERVING)",
       Service::kGateway,
       {{"service", "NAME",
         "only this service: gateway, mapping, planning, relocalization, modelproxy"}},
       Health,
       0},
  };
}

}  // namespace semnav::cli
