// Unary calls with the invocation's deadline, returning absl::Status.
#pragma once

#include <grpcpp/client_context.h>

#include "clients/cli/invocation.h"
#include "clients/cli/output.h"
#include "services/common/status/grpc_status.h"

namespace semnav::cli {

template <typename Stub, typename Request, typename Response>
absl::Status CallUnary(const Invocation& invocation, Stub& stub,
                       grpc::Status (Stub::*method)(grpc::ClientContext*, const Request&, Response*),
                       const Request& request, Response* response) {
  grpc::ClientContext context;
  invocation.SetDeadline(context, kDefaultUnaryDeadline);
  return FromGrpcStatus((stub.*method)(&context, request, response));
}

// Runs `body(stub)` with a stub of `GrpcService` on the channel to `service`; a channel that
// cannot be made (unreadable TLS file, missing token) is a usage error.
template <typename GrpcService, typename Body>
int WithStub(const Invocation& invocation, Service service, Body body) {
  absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = invocation.Channel(service);
  if (!channel.ok()) return UsageError(std::string(channel.status().message()));
  std::unique_ptr<typename GrpcService::Stub> stub = GrpcService::NewStub(*channel);
  return body(*stub);
}

}  // namespace semnav::cli
