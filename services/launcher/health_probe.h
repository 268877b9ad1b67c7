// One grpc.health.v1 Check against one service, over the same TLS/mTLS/token options the
// services use to reach each other: what container and orchestrator health checks run.
#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "services/common/cli/flags.h"
#include "services/common/client/channel.h"

namespace semnav::launcher {

// The serving status name ("SERVING", "NOT_SERVING", "SERVICE_UNKNOWN") for `service` ("" = the
// whole server), or the call's error with its gRPC code (UNAVAILABLE for a refused TLS
// handshake, UNAUTHENTICATED for a missing or wrong token, NOT_FOUND for an unknown service).
absl::StatusOr<std::string> ProbeHealth(const ClientOptions& client, const std::string& service,
                                        absl::Duration timeout);

// OK when GET `url` answers 2xx within `timeout` (the dashboard proxy's health check).
absl::Status ProbeHttp(const std::string& url, absl::Duration timeout);

// `semnav probe`: flags, run, print; exit 0 when SERVING, 1 otherwise, 2 on bad flags.
const std::vector<FlagSpec>& ProbeFlags();
std::string ProbeUsage();
int RunProbe(int argc, char** argv, int first);

}  // namespace semnav::launcher
