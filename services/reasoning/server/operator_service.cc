#include "services/reasoning/server/operator_service.h"

#include "services/common/status/grpc_status.h"
#include "services/reasoning/server/queued_writer.h"

namespace semnav::reasoning {
namespace {

// Finishes a unary call with `result`, storing the value through `store` when OK.
template <typename T, typename Store>
grpc::ServerUnaryReactor* Reply(grpc::CallbackServerContext* context, absl::StatusOr<T> result,
                                Store store) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  if (result.ok()) store(*std::move(result));
  reactor->Finish(ToGrpcStatus(result.status()));
  return reactor;
}

grpc::ServerUnaryReactor* Reply(grpc::CallbackServerContext* context, const absl::Status& status) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(ToGrpcStatus(status));
  return reactor;
}

// A server stream registered with the hub for its lifetime: `Watch` and `Unwatch` are the hub's
// member functions for the stream's message type.
template <typename Request, typename Response, auto Watch, auto Unwatch>
class HubStreamReactor : public QueuedWriter<grpc::ServerWriteReactor<Response>, Response> {
 public:
  HubStreamReactor(std::shared_ptr<GatewayHub> hub, const Request& request) : hub_(std::move(hub)) {
    ((*hub_).*Watch)(request, this);
  }
  void OnDone() override {
    ((*hub_).*Unwatch)(this);
    delete this;
  }

 private:
  std::shared_ptr<GatewayHub> hub_;
};

using TaskWatchReactor = HubStreamReactor<api::WatchTaskRequest, api::WatchTaskResponse,
                                          &GatewayHub::WatchTask, &GatewayHub::UnwatchTask>;
using EventReactor = HubStreamReactor<api::StreamEventsRequest, api::StreamEventsResponse,
                                      &GatewayHub::WatchEvents, &GatewayHub::UnwatchEvents>;
using FastTelemetryReactor =
    HubStreamReactor<api::StreamFastTelemetryRequest, api::StreamFastTelemetryResponse,
                     &GatewayHub::WatchFastTelemetry, &GatewayHub::UnwatchFastTelemetry>;
using SlowTelemetryReactor =
    HubStreamReactor<api::StreamSlowTelemetryRequest, api::StreamSlowTelemetryResponse,
                     &GatewayHub::WatchSlowTelemetry, &GatewayHub::UnwatchSlowTelemetry>;

}  // namespace

grpc::ServerUnaryReactor* OperatorServiceImpl::SubmitInstruction(
    grpc::CallbackServerContext* context, const api::SubmitInstructionRequest* request,
    api::SubmitInstructionResponse* response) {
  return Reply(context, hub_->Submit(*request),
               [&](api::SubmitInstructionResponse r) { *response = std::move(r); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::GetTask(grpc::CallbackServerContext* context,
                                                       const api::GetTaskRequest* request,
                                                       api::GetTaskResponse* response) {
  return Reply(context, hub_->GetTask(request->task_id()),
               [&](api::TaskSnapshot task) { *response->mutable_task() = std::move(task); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::ListTasks(grpc::CallbackServerContext* context,
                                                         const api::ListTasksRequest* request,
                                                         api::ListTasksResponse* response) {
  return Reply(context, hub_->ListTasks(*request),
               [&](api::ListTasksResponse r) { *response = std::move(r); });
}

grpc::ServerWriteReactor<api::WatchTaskResponse>* OperatorServiceImpl::WatchTask(
    grpc::CallbackServerContext*, const api::WatchTaskRequest* request) {
  return new TaskWatchReactor(hub_, *request);
}

grpc::ServerWriteReactor<api::StreamFastTelemetryResponse>*
OperatorServiceImpl::StreamFastTelemetry(grpc::CallbackServerContext*,
                                         const api::StreamFastTelemetryRequest* request) {
  return new FastTelemetryReactor(hub_, *request);
}

grpc::ServerWriteReactor<api::StreamSlowTelemetryResponse>*
OperatorServiceImpl::StreamSlowTelemetry(grpc::CallbackServerContext*,
                                         const api::StreamSlowTelemetryRequest* request) {
  return new SlowTelemetryReactor(hub_, *request);
}

grpc::ServerUnaryReactor* OperatorServiceImpl::CancelTask(grpc::CallbackServerContext* context,
                                                          const api::CancelTaskRequest* request,
                                                          api::CancelTaskResponse* response) {
  return Reply(context, hub_->Cancel(*request),
               [&](api::TaskSnapshot task) { *response->mutable_task() = std::move(task); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::PauseTask(grpc::CallbackServerContext* context,
                                                         const api::PauseTaskRequest* request,
                                                         api::PauseTaskResponse* response) {
  return Reply(context, hub_->Pause(*request),
               [&](api::TaskSnapshot task) { *response->mutable_task() = std::move(task); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::ResumeTask(grpc::CallbackServerContext* context,
                                                          const api::ResumeTaskRequest* request,
                                                          api::ResumeTaskResponse* response) {
  return Reply(context, hub_->Resume(*request),
               [&](api::TaskSnapshot task) { *response->mutable_task() = std::move(task); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::AcquireLease(grpc::CallbackServerContext* context,
                                                            const api::AcquireLeaseRequest* request,
                                                            api::AcquireLeaseResponse* response) {
  return Reply(context, hub_->AcquireLease(*request),
               [&](api::Lease lease) { *response->mutable_lease() = std::move(lease); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::RenewLease(grpc::CallbackServerContext* context,
                                                          const api::RenewLeaseRequest* request,
                                                          api::RenewLeaseResponse* response) {
  return Reply(context, hub_->RenewLease(*request),
               [&](api::Lease lease) { *response->mutable_lease() = std::move(lease); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::ReleaseLease(grpc::CallbackServerContext* context,
                                                            const api::ReleaseLeaseRequest* request,
                                                            api::ReleaseLeaseResponse*) {
  return Reply(context, hub_->ReleaseLease(*request));
}

grpc::ServerUnaryReactor* OperatorServiceImpl::EmergencyStop(
    grpc::CallbackServerContext* context, const api::EmergencyStopRequest* request,
    api::EmergencyStopResponse* response) {
  return Reply(context, hub_->EmergencyStop(*request),
               [&](api::EmergencyStopResponse r) { *response = std::move(r); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::RelocalizeRobot(
    grpc::CallbackServerContext* context, const api::RelocalizeRobotRequest* request,
    api::RelocalizeRobotResponse* response) {
  return Reply(context, hub_->RelocalizeRobot(*request),
               [&](api::RelocalizeRobotResponse r) { *response = std::move(r); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::ClearEmergencyStop(
    grpc::CallbackServerContext* context, const api::ClearEmergencyStopRequest* request,
    api::ClearEmergencyStopResponse*) {
  return Reply(context, hub_->ClearEmergencyStop(*request));
}

grpc::ServerWriteReactor<api::StreamEventsResponse>* OperatorServiceImpl::StreamEvents(
    grpc::CallbackServerContext*, const api::StreamEventsRequest* request) {
  return new EventReactor(hub_, *request);
}

grpc::ServerUnaryReactor* OperatorServiceImpl::ListEvents(grpc::CallbackServerContext* context,
                                                          const api::ListEventsRequest* request,
                                                          api::ListEventsResponse* response) {
  return Reply(context, hub_->ListEvents(*request),
               [&](api::ListEventsResponse r) { *response = std::move(r); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::DecomposeInstruction(
    grpc::CallbackServerContext* context, const api::DecomposeInstructionRequest* request,
    api::DecomposeInstructionResponse* response) {
  return Reply(context, hub_->Decompose(*request),
               [&](api::DecomposeInstructionResponse r) { *response = std::move(r); });
}

grpc::ServerUnaryReactor* OperatorServiceImpl::ResolveTarget(
    grpc::CallbackServerContext* context, const api::ResolveTargetRequest* request,
    api::ResolveTargetResponse* response) {
  absl::StatusOr<api::ResolveTargetResponse> fast = hub_->ResolveTarget(*request);
  if (!fast.ok() || !hub_->WantsSlowPath(*request, *fast)) {
    return Reply(context, std::move(fast),
                 [&](api::ResolveTargetResponse r) { *response = std::move(r); });
  }
  // The model answers later on another thread; the reactor finishes then (no thread waits).
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  hub_->ResolveSlow(*request, *std::move(fast),
                    [reactor, response](absl::StatusOr<api::ResolveTargetResponse> r) {
                      if (r.ok()) *response = *std::move(r);
                      reactor->Finish(ToGrpcStatus(r.status()));
                    });
  return reactor;
}

}  // namespace semnav::reasoning
