// Every MappingService request, served by the service as semnav-mapping builds it (store in a
// scratch folder, live snapshots off). See rpc_harness.h for the input format.
#include <cstdint>
#include <cstdlib>

#include "services/common/config/config_reader.h"
#include "services/mapping/server/mapping_config_yaml.h"
#include "services/mapping/server/mapping_service.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/rpc_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static semnav::fuzz::RpcHarness* harness = [] {
    semnav::ConfigReader section = semnav::ConfigReader::Empty();
    semnav::mapping::MappingServiceConfig config =
        *semnav::mapping::MappingServiceConfig::FromYaml(section);
    config.store_directory = semnav::fuzz::ScratchDir() + "/maps";
    config.live_snapshot_interval_s = 0;
    absl::StatusOr<semnav::mapping::MapStore> store =
        semnav::mapping::MapStore::Open(config.store_directory);
    if (!store.ok()) std::abort();
    std::unique_ptr<semnav::ServiceHost> host = semnav::fuzz::LoopbackHost("semnav-mapping");
    host->AddService(
        std::make_unique<semnav::mapping::MappingServiceImpl>(config, *std::move(store)),
        "semnav.mapping.v1.MappingService");
    return new semnav::fuzz::RpcHarness(
        std::move(host), {"semnav.mapping.v1.MappingService", "semnav.common.v1.MetricsService"});
  }();
  harness->Call(data, size);
  return 0;
}
