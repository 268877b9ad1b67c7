// Endpoints of services already running elsewhere (other hosts, TLS, tokens), for a simulator
// that does not start its own stack. The YAML has one client section per service, the keys of
// docs/operations.md's client reference (address, tls.*, auth.*):
//   gateway:  {address: 10.0.0.2:50050, tls: {ca_file: ca.crt, cert_file: robot.crt, key_file:
//   robot.key}} mapping:  {address: 127.0.0.1:50051} planning: {address: 10.0.0.2:50052, auth:
//   {token_file: robot.token}}
#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "clients/sim/loop/episode_spec.h"

namespace semnav::sim::loop {

// All three sections are required; unknown keys and unreadable files are errors naming them.
absl::StatusOr<Endpoints> LoadRemoteEndpoints(const std::string& yaml_path);

}  // namespace semnav::sim::loop
