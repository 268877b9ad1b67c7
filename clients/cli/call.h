// Unary calls with the invocation's deadline, and the plumbing every command shares.
#pragma once

#include <grpcpp/client_context.h>

#include <iostream>

#include "clients/cli/core/exit_codes.h"
#include "clients/cli/invocation.h"
#include "clients/cli/output.h"
#include "services/common/status/grpc_status.h"

namespace semnav::cli {

template <typename Stub, typename Request, typename Response>
absl::Status CallUnary(const Invocation& invocation, Stub& stub,
                       grpc::Status (Stub::*method)(grpc::ClientContext*, const Request&,
                                                    Response*),
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

// A whole single-call command: `method` on `service`, then the response as JSON with --json or
// as the text describe(response) returns.
template <typename GrpcService, typename Request, typename Response, typename Describe>
int RunUnary(const Invocation& invocation, Service service,
             grpc::Status (GrpcService::Stub::*method)(grpc::ClientContext*, const Request&,
                                                       Response*),
             const Request& request, Describe describe) {
  return WithStub<GrpcService>(invocation, service, [&](typename GrpcService::Stub& stub) {
    Response response;
    if (absl::Status status = CallUnary(invocation, stub, method, request, &response);
        !status.ok()) {
      return Fail(status);
    }
    if (invocation.json()) {
      PrintJson(response);
    } else {
      std::cout << describe(response);
    }
    return ToInt(ExitCode::kOk);
  });
}

}  // namespace semnav::cli
