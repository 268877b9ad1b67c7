#include "services/modelproxy/server/model_proxy_service.h"

#include "absl/time/clock.h"
#include "services/common/status/grpc_status.h"
#include "services/modelproxy/server/proto_convert.h"

namespace semnav::modelproxy {
namespace {

std::string Metadata(const grpc::CallbackServerContext& context, const char* key) {
  auto it = context.client_metadata().find(key);
  return it == context.client_metadata().end() ? ""
                                               : std::string(it->second.data(), it->second.size());
}

CallerId Caller(const grpc::CallbackServerContext& context) {
  return CallerId{Metadata(context, kRobotIdMetadata), Metadata(context, kTaskIdMetadata)};
}

// The earlier of the gRPC deadline and now + the request's own timeout (when set).
absl::Time Deadline(const grpc::CallbackServerContext& context,
                    const google::protobuf::Duration& timeout) {
  absl::Time deadline = absl::InfiniteFuture();
  if (context.deadline() != std::chrono::system_clock::time_point::max()) {
    deadline = absl::FromChrono(context.deadline());
  }
  const absl::Duration own = absl::Seconds(timeout.seconds()) + absl::Nanoseconds(timeout.nanos());
  if (own > absl::ZeroDuration()) deadline = std::min(deadline, absl::Now() + own);
  return deadline;
}

}  // namespace

ModelProxyServiceImpl::ModelProxyServiceImpl(std::unique_ptr<ModelProxy> proxy,
                                             std::string default_alias, int worker_threads)
    : proxy_(std::move(proxy)),
      default_alias_(std::move(default_alias)),
      workers_(worker_threads) {}

grpc::ServerUnaryReactor* ModelProxyServiceImpl::RunOnWorker(grpc::CallbackServerContext* context,
                                                             std::function<grpc::Status()> job) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  if (!workers_.Submit([reactor, job = std::move(job)] { reactor->Finish(job()); })) {
    reactor->Finish(grpc::Status(grpc::StatusCode::UNAVAILABLE, "model proxy is shutting down"));
  }
  return reactor;
}

grpc::ServerUnaryReactor* ModelProxyServiceImpl::Complete(grpc::CallbackServerContext* context,
                                                          const v1::CompleteRequest* request,
                                                          v1::CompleteResponse* response) {
  const CallerId caller = Caller(*context);
  const absl::Time deadline = Deadline(*context, request->timeout());
  return RunOnWorker(context, [this, request, response, caller, deadline] {
    absl::StatusOr<CompletionRequest> core = ToCore(*request);
    if (!core.ok()) return ToGrpcStatus(core.status());
    absl::StatusOr<CompletionResult> result = proxy_->Complete(*std::move(core), caller, deadline);
    if (!result.ok()) return ToGrpcStatus(result.status());
    ToProto(*result, response);
    return grpc::Status::OK;
  });
}

grpc::ServerUnaryReactor* ModelProxyServiceImpl::Embed(grpc::CallbackServerContext* context,
                                                       const v1::EmbedRequest* request,
                                                       v1::EmbedResponse* response) {
  const CallerId caller = Caller(*context);
  const absl::Time deadline = Deadline(*context, request->timeout());
  return RunOnWorker(context, [this, request, response, caller, deadline] {
    absl::StatusOr<EmbeddingResult> result = proxy_->Embed(ToCore(*request), caller, deadline);
    if (!result.ok()) return ToGrpcStatus(result.status());
    ToProto(*result, response);
    return grpc::Status::OK;
  });
}

grpc::ServerUnaryReactor* ModelProxyServiceImpl::ListBackends(
    grpc::CallbackServerContext* context, const v1::ListBackendsRequest* /*request*/,
    v1::ListBackendsResponse* response) {
  for (const BackendStatus& status : proxy_->ListBackends(absl::Now()))
    ToProto(status, response->add_backends());
  for (const auto& [alias, chain] : proxy_->Aliases()) {
    v1::AliasInfo* info = response->add_aliases();
    info->set_alias(alias);
    for (const std::string& name : chain) info->add_chain(name);
  }
  response->set_default_alias(default_alias_);
  response->set_cache_entries(proxy_->cache_entries());
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(grpc::Status::OK);
  return reactor;
}

grpc::ServerUnaryReactor* ModelProxyServiceImpl::GetUsage(grpc::CallbackServerContext* context,
                                                          const v1::GetUsageRequest* request,
                                                          v1::GetUsageResponse* response) {
  for (const UsageRow& row : proxy_->usage().Query(request->robot_id(), request->task_id())) {
    ToProto(row, response->add_records());
  }
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(grpc::Status::OK);
  return reactor;
}

}  // namespace semnav::modelproxy
