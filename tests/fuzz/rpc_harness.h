// The RPC harnesses' driver: one service, built as its main() builds it, is hosted by the real
// ServiceHost (interceptors, message limits) on a loopback port. Each fuzz input is one call:
// the first byte picks a method of the hosted services (descriptor order, as the request sweep
// enumerates them) and the rest is the request's bytes, sent raw through grpc::GenericStub, so
// parsing, the adapter's validation and its proto-to-core conversion all run. A call must end
// with a status other than INTERNAL or UNKNOWN (as tests/contract/request_sweep_test.cc asserts);
// streams still open after a short grace are cancelled. For client- and bidi-streaming methods
// the bytes are a sequence of messages, each a 2-byte little-endian length and that many bytes
// (a last incomplete one is sent as it is), so a session's hello can precede its state.
#pragma once

#include <google/protobuf/descriptor.h>
#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "services/common/server/service_host.h"

namespace semnav::fuzz {

class RpcHarness {
 public:
  // Starts `host` (already given its services) and lists the methods of `services` (full names).
  RpcHarness(std::unique_ptr<ServiceHost> host, const std::vector<std::string>& services);
  // One call from one fuzz input; aborts when the call breaks the contract above.
  void Call(const uint8_t* data, size_t size);

 private:
  std::unique_ptr<ServiceHost> host_;
  std::shared_ptr<grpc::Channel> channel_;
  std::vector<const google::protobuf::MethodDescriptor*> methods_;
};

// The messages of a streaming call's input (format above).
std::vector<std::string> SplitStreamMessages(const uint8_t* data, size_t size);

// A ServiceHost on 127.0.0.1 with a free port and default limits.
std::unique_ptr<ServiceHost> LoopbackHost(const std::string& binary_name);

}  // namespace semnav::fuzz
