// gRPC C++ 1.51 answers a callback-API unary or server-streaming request whose bytes do not
// parse with UNIMPLEMENTED and an empty message (server_callback_handlers.h: the handler gets a
// failed deserialization status and installs an "Unimplemented" reactor). Clients then believe
// the method does not exist. This interceptor, installed once by ServiceHost for every service,
// sees the request message missing after POST_RECV_MESSAGE and rewrites that one status to
// INVALID_ARGUMENT "request: could not be parsed as <type> ..." with ErrorInfo
// {reason: REQUEST_NOT_PARSED}.
//
// Bidi streams cannot be covered here: gRPC reports a stream message that does not parse to the
// reactor exactly like the end of the client's stream (OnReadDone(false)), and the interceptor
// sees the same null message for both.
#pragma once

#include <grpcpp/support/server_interceptor.h>

namespace semnav {

inline constexpr char kRequestNotParsedReason[] = "REQUEST_NOT_PARSED";

class RequestParseInterceptorFactory
    : public grpc::experimental::ServerInterceptorFactoryInterface {
 public:
  grpc::experimental::Interceptor* CreateServerInterceptor(
      grpc::experimental::ServerRpcInfo* info) override;
};

}  // namespace semnav
