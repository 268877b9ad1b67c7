// semnav-planning: the planning service (seed 003 improved Jump A*, JPS/A*
// with the seed 004 alternative point, exploration strategies, smoothing)
// behind gRPC.
#include <memory>

#include "services/common/client/channel.h"
#include "services/common/server/service_binary.h"
#include "services/planning/server/planning_config.h"
#include "services/planning/server/planning_service.h"

int main(int argc, char** argv) {
  semnav::ServiceBinarySpec spec;
  spec.binary = "semnav-planning";
  spec.summary =
      "Planning: JPS/A*, multi-modal improved Jump A*, alternative point, exploration goals,"
      " trajectory smoothing";
  spec.default_listen = "127.0.0.1:50052";
  spec.config_section = "planning";
  spec.setup = [](semnav::ConfigReader& section, semnav::ServiceHost& host) -> absl::Status {
    absl::StatusOr<semnav::planning::PlanningConfig> config =
        semnav::planning::PlanningConfig::FromYaml(section);
    if (!config.ok()) return config.status();
    absl::StatusOr<std::shared_ptr<grpc::Channel>> mapping = semnav::MakeChannel(config->mapping);
    if (!mapping.ok()) return mapping.status();
    auto service = std::make_unique<semnav::planning::PlanningServiceImpl>(*std::move(config),
                                                                           *std::move(mapping));
    semnav::planning::PlanningServiceImpl* raw = service.get();
    host.OnShutdown([raw] { raw->Shutdown(); });
    host.AddService(std::move(service), "semnav.planning.v1.PlanningService");
    return absl::OkStatus();
  };
  return semnav::RunServiceBinary(argc, argv, spec);
}
