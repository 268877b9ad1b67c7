// semnav-mapping: RGB-D frames -> OctoMap, hierarchical grid, semantic map, scene graph.
#include <memory>

#include "services/common/server/service_binary.h"
#include "services/mapping/core/map_store.h"
#include "services/mapping/server/mapping_config_yaml.h"
#include "services/mapping/server/mapping_service.h"

int main(int argc, char** argv) {
  semnav::ServiceBinarySpec spec;
  spec.binary = "semnav-mapping";
  spec.summary = "Mapping service: sensor frames in; OctoMap, layered grid and scene graph out.";
  spec.default_listen = "127.0.0.1:50051";
  spec.config_section = "mapping";
  spec.setup = [](semnav::ConfigReader& section, semnav::ServiceHost& host) -> absl::Status {
    absl::StatusOr<semnav::mapping::MappingServiceConfig> config =
        semnav::mapping::MappingServiceConfig::FromYaml(section);
    if (!config.ok()) return config.status();
    absl::StatusOr<semnav::mapping::MapStore> store =
        semnav::mapping::MapStore::Open(config->store_directory);
    if (!store.ok()) return store.status();
    auto service = std::make_unique<semnav::mapping::MappingServiceImpl>(*std::move(config),
                                                                         *std::move(store));
    if (absl::Status live = service->StartLiveSnapshots(); !live.ok()) return live;
    if (absl::Status pushed = service->StartLandmarkPublisher(); !pushed.ok()) return pushed;
    semnav::mapping::MappingServiceImpl* raw = service.get();
    host.OnShutdown([raw] { raw->Shutdown(); });
    host.AddService(std::move(service), "semnav.mapping.v1.MappingService");
    return absl::OkStatus();
  };
  return semnav::RunServiceBinary(argc, argv, spec);
}
