// Each service's config file, read the way RunServiceBinary reads it (services/common/server/
// service_binary.cc): log_level, the server section, then the service's own section, then
// Finish(). The first byte picks the service; the rest is the YAML text.
#include <cstdint>

#include "services/common/config/config_reader.h"
#include "services/common/logging/log.h"
#include "services/common/server/server_options.h"
#include "services/mapping/server/mapping_config_yaml.h"
#include "services/modelproxy/server/proxy_config.h"
#include "services/planning/server/planning_config.h"
#include "services/reasoning/server/gateway_config.h"
#include "services/relocalization/server/service_config.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using semnav::ConfigReader;

void ReadServiceSection(uint8_t service, ConfigReader& root) {
  switch (service % 5) {
    case 0: {
      ConfigReader section = root.Child("mapping");
      (void)semnav::mapping::MappingServiceConfig::FromYaml(section);
      break;
    }
    case 1: {
      ConfigReader section = root.Child("planning");
      (void)semnav::planning::PlanningConfig::FromYaml(section);
      break;
    }
    case 2: {
      ConfigReader section = root.Child("relocalization");
      (void)semnav::relocalization::ServiceConfig::FromYaml(section);
      break;
    }
    case 3: {
      ConfigReader section = root.Child("modelproxy");
      (void)semnav::modelproxy::BuildProxyFromConfig(section, semnav::modelproxy::ProxyOptions());
      break;
    }
    default: {
      ConfigReader section = root.Child("gateway");
      (void)semnav::reasoning::GatewayConfig::FromYaml(section);
      break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  absl::StatusOr<ConfigReader> root =
      ConfigReader::FromString(semnav::fuzz::AsString(data + 1, size - 1));
  if (!root.ok()) return 0;
  std::string level = "warning";
  root->Read("log_level", &level);
  (void)semnav::ParseLogLevel(level);
  ConfigReader server = root->Child("server");
  (void)semnav::ServerOptions::FromConfig(server, semnav::ServerOptions());
  ReadServiceSection(data[0], *root);
  (void)root->Finish();
  return 0;
}
