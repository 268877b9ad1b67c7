// Every RelocalizationService request, served by the service as semnav-relocalization builds it
// with default settings (landmark maps in memory, no ONNX detector). See rpc_harness.h.
#include <cstdint>
#include <cstdlib>

#include "services/common/config/config_reader.h"
#include "services/relocalization/core/landmark_store.h"
#include "services/relocalization/server/relocalization_service.h"
#include "services/relocalization/server/service_config.h"
#include "tests/fuzz/rpc_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace semnav::relocalization;
  static semnav::fuzz::RpcHarness* harness = [] {
    semnav::ConfigReader section = semnav::ConfigReader::Empty();
    absl::StatusOr<ServiceConfig> config = ServiceConfig::FromYaml(section);
    if (!config.ok()) std::abort();
    absl::StatusOr<std::unique_ptr<LandmarkStore>> store =
        LandmarkStore::Open(config->storage_dir, config->merge);
    if (!store.ok()) std::abort();
    std::unique_ptr<semnav::ServiceHost> host = semnav::fuzz::LoopbackHost("semnav-relocalization");
    host->AddService(
        std::make_unique<RelocalizationServiceImpl>(*config, *std::move(store), nullptr),
        "semnav.relocalization.v1.RelocalizationService");
    return new semnav::fuzz::RpcHarness(std::move(host),
                                        {"semnav.relocalization.v1.RelocalizationService"});
  }();
  harness->Call(data, size);
  return 0;
}
