// semnav-relocalization: generalized-object landmark maps, relocalization and two-robot
// map alignment (seed 001).
#include <memory>

#include "services/common/server/service_binary.h"
#include "services/relocalization/core/landmark_store.h"
#include "services/relocalization/core/onnx_heads.h"
#include "services/relocalization/server/relocalization_service.h"
#include "services/relocalization/server/service_config.h"

namespace {

absl::Status Setup(semnav::ConfigReader& section, semnav::ServiceHost& host) {
  using namespace semnav::relocalization;
  absl::StatusOr<ServiceConfig> config = ServiceConfig::FromYaml(section);
  if (!config.ok()) return config.status();
  absl::StatusOr<std::unique_ptr<LandmarkStore>> store =
      LandmarkStore::Open(config->storage_dir, config->merge);
  if (!store.ok()) return store.status();
  std::unique_ptr<OnnxHeads> detector;
  if (!config->detector.model_path.empty()) {
    absl::StatusOr<std::unique_ptr<OnnxHeads>> loaded = OnnxHeads::Load(config->detector);
    if (!loaded.ok()) return loaded.status();
    detector = *std::move(loaded);
  }
  host.AddService(
      std::make_unique<RelocalizationServiceImpl>(*config, *std::move(store), std::move(detector)),
      "semnav.relocalization.v1.RelocalizationService");
  return absl::OkStatus();
}

}  // namespace

int main(int argc, char** argv) {
  return semnav::RunServiceBinary(
      argc, argv,
      {"semnav-relocalization",
       "Relocalization on generalized-object landmark maps; two-robot map alignment",
       "127.0.0.1:50053", "relocalization", Setup});
}
