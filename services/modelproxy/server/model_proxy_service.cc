#include "services/modelproxy/server/model_proxy_service.h"

#include "absl/strings/cord.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "services/common/status/field_error.h"
#include "services/common/status/grpc_status.h"
#include "services/common/status/value_checks.h"
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

// A request's own time budget: unset/zero = none; otherwise positive and at most a day (the
// proxy caps it further at max_deadline_s).
constexpr int64_t kMaxTimeoutS = 86400;

absl::Status ValidateTimeout(const google::protobuf::Duration& timeout) {
  if (timeout.seconds() < 0 || timeout.seconds() > kMaxTimeoutS) {
    return InvalidField("timeout.seconds", absl::StrCat("must be in [0, ", kMaxTimeoutS, "]"));
  }
  if (timeout.nanos() < 0 || timeout.nanos() > 999999999) {
    return InvalidField("timeout.nanos", "must be in [0, 999999999]");
  }
  return absl::OkStatus();
}

// Caller ids key the usage ledger: bounded like every other id.
absl::Status ValidateCaller(const CallerId& caller) {
  if (auto s = CheckLength(caller.robot_id, kRobotIdMetadata, kMaxIdBytes); !s.ok()) return s;
  return CheckLength(caller.task_id, kTaskIdMetadata, kMaxIdBytes);
}

grpc::ServerUnaryReactor* Finish(grpc::CallbackServerContext* context, const absl::Status& status) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(ToGrpcStatus(status));
  return reactor;
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
    absl::Status stopping = absl::UnavailableError("model proxy is shutting down");
    stopping.SetPayload(kReasonPayloadUrl, absl::Cord("SHUTTING_DOWN"));
    reactor->Finish(ToGrpcStatus(stopping));
  }
  return reactor;
}

grpc::ServerUnaryReactor* ModelProxyServiceImpl::Complete(grpc::CallbackServerContext* context,
                                                          const v1::CompleteRequest* request,
                                                          v1::CompleteResponse* response) {
  const CallerId caller = Caller(*context);
  if (absl::Status s = ValidateCaller(caller); !s.ok()) return Finish(context, s);
  if (absl::Status s = ValidateTimeout(request->timeout()); !s.ok()) return Finish(context, s);
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
  if (absl::Status s = ValidateCaller(caller); !s.ok()) return Finish(context, s);
  if (absl::Status s = ValidateTimeout(request->timeout()); !s.ok()) return Finish(context, s);
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
  return Finish(context, absl::OkStatus());
}

grpc::ServerUnaryReactor* ModelProxyServiceImpl::GetUsage(grpc::CallbackServerContext* context,
                                                          const v1::GetUsageRequest* request,
                                                          v1::GetUsageResponse* response) {
  if (auto s = CheckLength(request->robot_id(), "robot_id", kMaxIdBytes); !s.ok()) {
    return Finish(context, s);
  }
  if (auto s = CheckLength(request->task_id(), "task_id", kMaxIdBytes); !s.ok()) {
    return Finish(context, s);
  }
  for (const UsageRow& row : proxy_->usage().Query(request->robot_id(), request->task_id())) {
    ToProto(row, response->add_records());
  }
  return Finish(context, absl::OkStatus());
}

}  // namespace semnav::modelproxy
