// Every PlanningService request, served by the service as semnav-planning builds it with default
// settings; its mapping channel points at a closed port, so live-map requests fail UNAVAILABLE.
// See rpc_harness.h for the input format.
#include <cstdint>
#include <cstdlib>

#include "services/common/client/channel.h"
#include "services/common/config/config_reader.h"
#include "services/planning/server/planning_config.h"
#include "services/planning/server/planning_service.h"
#include "tests/fuzz/rpc_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static semnav::fuzz::RpcHarness* harness = [] {
    semnav::ConfigReader section = semnav::ConfigReader::Empty();
    absl::StatusOr<semnav::planning::PlanningConfig> config =
        semnav::planning::PlanningConfig::FromYaml(section);
    if (!config.ok()) std::abort();
    config->mapping.address = "127.0.0.1:1";
    absl::StatusOr<std::shared_ptr<grpc::Channel>> mapping = semnav::MakeChannel(config->mapping);
    if (!mapping.ok()) std::abort();
    std::unique_ptr<semnav::ServiceHost> host = semnav::fuzz::LoopbackHost("semnav-planning");
    host->AddService(std::make_unique<semnav::planning::PlanningServiceImpl>(*std::move(config),
                                                                             *std::move(mapping)),
                     "semnav.planning.v1.PlanningService");
    return new semnav::fuzz::RpcHarness(std::move(host), {"semnav.planning.v1.PlanningService"});
  }();
  harness->Call(data, size);
  return 0;
}
