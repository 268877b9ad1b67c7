#pragma once

#include <functional>
#include <string>

#include "absl/status/status.h"
#include "services/common/config/config_reader.h"
#include "services/common/server/service_host.h"

namespace semnav {

// What distinguishes one semnav server binary from another.
struct ServiceBinarySpec {
  std::string binary;          // e.g. "semnav-mapping"
  std::string summary;         // one line for --help
  std::string default_listen;  // e.g. "127.0.0.1:50051"
  std::string config_section;  // YAML key of the service's own settings, e.g. "mapping"
  // Builds the service from its config section and adds it to the host. Settings errors
  // should be recorded on `section` (they are reported with their key path before start).
  std::function<absl::Status(ConfigReader& section, ServiceHost& host)> setup;
};

// The whole main(): --help/--config/--listen/--log_level (ParseFlagsOrExit: unknown flags exit 2
// with the usage), config loading (unknown keys and bad values fail with their path, exit 2),
// serving, and a graceful stop on SIGTERM/SIGINT (exit 0). Prints "<binary> serving on
// <host>:<port>" on stdout once healthy.
int RunServiceBinary(int argc, char** argv, const ServiceBinarySpec& spec);

}  // namespace semnav
