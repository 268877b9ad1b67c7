#include "clients/sim/loop/remote_endpoints.h"

#include "absl/strings/str_cat.h"
#include "services/common/client/channel.h"
#include "services/common/config/config_reader.h"

namespace semnav::sim::loop {

absl::StatusOr<Endpoints> LoadRemoteEndpoints(const std::string& yaml_path) {
  absl::StatusOr<ConfigReader> config = ConfigReader::FromFile(yaml_path);
  if (!config.ok()) return config.status();
  ClientOptions options[3];
  const char* names[3] = {"gateway", "mapping", "planning"};
  for (int i = 0; i < 3; ++i) {
    config->Check(config->Has(names[i]), names[i], "missing: every client section is required");
    ConfigReader section = config->Child(names[i]);
    options[i] = ClientOptions::FromConfig(section, ClientOptions{});
  }
  if (absl::Status s = config->Finish(); !s.ok())
    return absl::InvalidArgumentError(absl::StrCat(yaml_path, ": ", s.message()));
  std::shared_ptr<grpc::Channel> channels[3];
  for (int i = 0; i < 3; ++i) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = MakeChannel(options[i]);
    if (!channel.ok())
      return absl::Status(channel.status().code(),
                          absl::StrCat(names[i], ".", channel.status().message()));
    channels[i] = *channel;
  }
  return Endpoints{channels[0], channels[1], channels[2], nullptr};
}

}  // namespace semnav::sim::loop
