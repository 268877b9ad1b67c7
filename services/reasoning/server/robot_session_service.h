// RobotSessionService: one bidirectional stream per robot (callback API).
#pragma once

#include <memory>

#include "semnav/reasoning/v1/robot_session.grpc.pb.h"
#include "services/reasoning/server/gateway_hub.h"

namespace semnav::reasoning {

class RobotSessionServiceImpl : public api::RobotSessionService::CallbackService {
 public:
  explicit RobotSessionServiceImpl(std::shared_ptr<GatewayHub> hub) : hub_(std::move(hub)) {}

  grpc::ServerBidiReactor<api::ConnectRequest, api::ConnectResponse>* Connect(
      grpc::CallbackServerContext* context) override;

 private:
  std::shared_ptr<GatewayHub> hub_;
};

}  // namespace semnav::reasoning
