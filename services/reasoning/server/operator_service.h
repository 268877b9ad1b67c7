// OperatorService over the gateway hub (callback API).
#pragma once

#include <memory>

#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "services/reasoning/server/gateway_hub.h"

namespace semnav::reasoning {

class OperatorServiceImpl : public api::OperatorService::CallbackService {
 public:
  explicit OperatorServiceImpl(std::shared_ptr<GatewayHub> hub) : hub_(std::move(hub)) {}

  grpc::ServerUnaryReactor* SubmitInstruction(grpc::CallbackServerContext* context,
                                              const api::SubmitInstructionRequest* request,
                                              api::SubmitInstructionResponse* response) override;
  grpc::ServerUnaryReactor* GetTask(grpc::CallbackServerContext* context,
                                    const api::GetTaskRequest* request,
                                    api::GetTaskResponse* response) override;
  grpc::ServerUnaryReactor* ListTasks(grpc::CallbackServerContext* context,
                                      const api::ListTasksRequest* request,
                                      api::ListTasksResponse* response) override;
  grpc::ServerWriteReactor<api::WatchTaskResponse>* WatchTask(
      grpc::CallbackServerContext* context, const api::WatchTaskRequest* request) override;
  grpc::ServerUnaryReactor* CancelTask(grpc::CallbackServerContext* context,
                                       const api::CancelTaskRequest* request,
                                       api::CancelTaskResponse* response) override;
  grpc::ServerUnaryReactor* PauseTask(grpc::CallbackServerContext* context,
                                      const api::PauseTaskRequest* request,
                                      api::PauseTaskResponse* response) override;
  grpc::ServerUnaryReactor* ResumeTask(grpc::CallbackServerContext* context,
                                       const api::ResumeTaskRequest* request,
                                       api::ResumeTaskResponse* response) override;
  grpc::ServerUnaryReactor* AcquireLease(grpc::CallbackServerContext* context,
                                         const api::AcquireLeaseRequest* request,
                                         api::AcquireLeaseResponse* response) override;
  grpc::ServerUnaryReactor* RenewLease(grpc::CallbackServerContext* context,
                                       const api::RenewLeaseRequest* request,
                                       api::RenewLeaseResponse* response) override;
  grpc::ServerUnaryReactor* ReleaseLease(grpc::CallbackServerContext* context,
                                         const api::ReleaseLeaseRequest* request,
                                         api::ReleaseLeaseResponse* response) override;
  grpc::ServerUnaryReactor* EmergencyStop(grpc::CallbackServerContext* context,
                                          const api::EmergencyStopRequest* request,
                                          api::EmergencyStopResponse* response) override;
  grpc::ServerUnaryReactor* ClearEmergencyStop(grpc::CallbackServerContext* context,
                                               const api::ClearEmergencyStopRequest* request,
                                               api::ClearEmergencyStopResponse* response) override;
  grpc::ServerWriteReactor<api::StreamFastTelemetryResponse>* StreamFastTelemetry(
      grpc::CallbackServerContext* context,
      const api::StreamFastTelemetryRequest* request) override;
  grpc::ServerWriteReactor<api::StreamSlowTelemetryResponse>* StreamSlowTelemetry(
      grpc::CallbackServerContext* context,
      const api::StreamSlowTelemetryRequest* request) override;
  grpc::ServerWriteReactor<api::StreamEventsResponse>* StreamEvents(
      grpc::CallbackServerContext* context, const api::StreamEventsRequest* request) override;
  grpc::ServerUnaryReactor* ListEvents(grpc::CallbackServerContext* context,
                                       const api::ListEventsRequest* request,
                                       api::ListEventsResponse* response) override;
  grpc::ServerUnaryReactor* DecomposeInstruction(
      grpc::CallbackServerContext* context, const api::DecomposeInstructionRequest* request,
      api::DecomposeInstructionResponse* response) override;
  grpc::ServerUnaryReactor* ResolveTarget(grpc::CallbackServerContext* context,
                                          const api::ResolveTargetRequest* request,
                                          api::ResolveTargetResponse* response) override;
  grpc::ServerUnaryReactor* RelocalizeRobot(grpc::CallbackServerContext* context,
                                            const api::RelocalizeRobotRequest* request,
                                            api::RelocalizeRobotResponse* response) override;

 private:
  std::shared_ptr<GatewayHub> hub_;
};

}  // namespace semnav::reasoning
