#include "tests/fuzz/rpc_harness.h"

#include <grpcpp/generic/generic_stub.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "absl/strings/str_cat.h"

namespace semnav::fuzz {
namespace {

// Every call ends within this, streams included (the harness cancels open ones).
constexpr auto kCallDeadline = std::chrono::seconds(3);
// A stream that sent nothing for this long is answering a valid request: cancel it.
constexpr auto kOpenStreamGrace = std::chrono::milliseconds(30);

}  // namespace

std::vector<std::string> SplitStreamMessages(const uint8_t* data, size_t size) {
  std::vector<std::string> messages;
  size_t at = 0;
  while (size - at >= 2 && messages.size() < 64) {
    const size_t length = data[at] | (size_t{data[at + 1]} << 8);
    at += 2;
    const size_t taken = std::min(length, size - at);
    messages.emplace_back(reinterpret_cast<const char*>(data + at), taken);
    at += taken;
  }
  if (at < size) messages.emplace_back(reinterpret_cast<const char*>(data + at), size - at);
  return messages;
}

std::unique_ptr<ServiceHost> LoopbackHost(const std::string& binary_name) {
  ServerOptions options;
  options.listen = "127.0.0.1:0";
  options.shutdown_grace_s = 0.1;
  return std::make_unique<ServiceHost>(binary_name, options);
}

RpcHarness::RpcHarness(std::unique_ptr<ServiceHost> host, const std::vector<std::string>& services)
    : host_(std::move(host)) {
  if (absl::Status started = host_->Start(); !started.ok()) {
    std::fprintf(stderr, "service host: %s\n", started.ToString().c_str());
    std::abort();
  }
  channel_ = grpc::CreateChannel(absl::StrCat("127.0.0.1:", host_->port()),
                                 grpc::InsecureChannelCredentials());
  for (const std::string& name : services) {
    const google::protobuf::ServiceDescriptor* service =
        google::protobuf::DescriptorPool::generated_pool()->FindServiceByName(name);
    if (service == nullptr) {
      std::fprintf(stderr, "no descriptor for %s\n", name.c_str());
      std::abort();
    }
    for (int i = 0; i < service->method_count(); ++i) methods_.push_back(service->method(i));
  }
}

void RpcHarness::Call(const uint8_t* data, size_t size) {
  if (size == 0) return;
  const google::protobuf::MethodDescriptor* method = methods_[data[0] % methods_.size()];
  const std::string path = absl::StrCat("/", method->service()->full_name(), "/", method->name());
  grpc::GenericStub stub(channel_);
  grpc::CompletionQueue queue;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + kCallDeadline);
  std::unique_ptr<grpc::GenericClientAsyncReaderWriter> call =
      stub.PrepareCall(&context, path, &queue);
  // One operation is outstanding at a time, so the next event is the one awaited.
  auto await = [&](std::chrono::system_clock::time_point until) -> std::optional<bool> {
    void* tag = nullptr;
    bool ok = false;
    if (queue.AsyncNext(&tag, &ok, until) == grpc::CompletionQueue::TIMEOUT) return std::nullopt;
    return ok;
  };
  const auto hard_limit =
      std::chrono::system_clock::now() + kCallDeadline + std::chrono::seconds(2);
  bool hung = false;
  auto step = [&] {
    std::optional<bool> ok = await(hard_limit);
    if (!ok) hung = true;
    return ok.value_or(false);
  };
  call->StartCall(nullptr);
  step();
  const std::vector<std::string> messages =
      method->client_streaming() ? SplitStreamMessages(data + 1, size - 1)
                                 : std::vector<std::string>{std::string(
                                       reinterpret_cast<const char*>(data + 1), size - 1)};
  for (const std::string& message : messages) {
    grpc::Slice slice(message);
    grpc::ByteBuffer request(&slice, 1);
    call->Write(request, nullptr);
    if (!step()) break;
  }
  call->WritesDone(nullptr);
  step();
  while (!hung) {
    grpc::ByteBuffer response;
    call->Read(&response, nullptr);
    std::optional<bool> ok =
        await(method->server_streaming() ? std::chrono::system_clock::now() + kOpenStreamGrace
                                         : hard_limit);
    if (!ok && method->server_streaming()) {
      context.TryCancel();
      ok = await(hard_limit);
    }
    if (!ok) hung = true;
    if (!ok.value_or(false)) break;
  }
  if (hung) context.TryCancel();
  grpc::Status status;
  call->Finish(&status, nullptr);
  if (!await(hard_limit + std::chrono::seconds(2))) hung = true;
  queue.Shutdown();
  void* tag = nullptr;
  bool ok = false;
  while (queue.Next(&tag, &ok)) {
  }
  if (hung) {
    std::fprintf(stderr, "%s: the call did not end by its deadline\n", path.c_str());
    std::abort();
  }
  if (status.error_code() == grpc::StatusCode::INTERNAL ||
      status.error_code() == grpc::StatusCode::UNKNOWN) {
    std::fprintf(stderr, "%s: %d %s\n", path.c_str(), status.error_code(),
                 status.error_message().c_str());
    std::abort();
  }
}

}  // namespace semnav::fuzz
