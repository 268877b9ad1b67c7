#include "services/reasoning/server/robot_session_service.h"

#include "services/common/logging/log.h"
#include "services/common/status/grpc_status.h"
#include "services/reasoning/server/queued_writer.h"
#include "services/reasoning/server/request_checks.h"

namespace semnav::reasoning {
namespace {

// Reads hello, then states, feedback and camera frames; the hub writes commands through the queued
// writer.
class SessionReactor
    : public QueuedWriter<grpc::ServerBidiReactor<api::ConnectRequest, api::ConnectResponse>,
                          api::ConnectResponse> {
 public:
  explicit SessionReactor(std::shared_ptr<GatewayHub> hub) : hub_(std::move(hub)) {
    StartRead(&request_);
  }

  void OnReadDone(bool ok) override {
    if (!ok) {  // the robot closed its side or the call ended
      hub_->CloseSession(this);
      Close(grpc::Status::OK);
      return;
    }
    absl::Status status = Handle();
    if (!status.ok()) {
      hub_->CloseSession(this);
      Close(ToGrpcStatus(status));
      return;
    }
    StartRead(&request_);
  }

  void OnDone() override {
    hub_->CloseSession(this);
    delete this;
  }

 private:
  absl::Status Handle() {
    if (!open_) {
      if (!request_.has_hello()) {
        return FieldError(absl::StatusCode::kInvalidArgument, "hello",
                          "the first message must be a hello");
      }
      absl::StatusOr<api::SessionAccepted> accepted = hub_->OpenSession(request_.hello(), this);
      open_ = accepted.ok();
      return accepted.status();
    }
    switch (request_.body_case()) {
      // A bad state or feedback ends the session with INVALID_ARGUMENT naming the field (the
      // robot has no other error channel); the task pauses and the last good pose is kept.
      case api::ConnectRequest::kState:
        return hub_->OnRobotState(this, request_.state());
      case api::ConnectRequest::kFeedback:
        return hub_->OnFeedback(this, request_.feedback());
      case api::ConnectRequest::kCamera:
        // Malformed numbers end the session like a bad state; an image that does not decode is
        // the camera's problem, not the session's: logged, and the stream goes on.
        if (absl::Status malformed = Validate(request_.camera()); !malformed.ok()) return malformed;
        if (absl::Status status = hub_->OnCameraFrame(this, request_.camera()); !status.ok()) {
          LogWarning("camera_frame_rejected", {{"message", status.message()}});
        }
        return absl::OkStatus();
      case api::ConnectRequest::kHello:
        return FieldError(absl::StatusCode::kInvalidArgument, "hello",
                          "only the first message may be a hello");
      case api::ConnectRequest::BODY_NOT_SET:
        break;
    }
    return FieldError(absl::StatusCode::kInvalidArgument, "body", "empty message");
  }

  std::shared_ptr<GatewayHub> hub_;
  api::ConnectRequest request_;
  bool open_ = false;
};

}  // namespace

grpc::ServerBidiReactor<api::ConnectRequest, api::ConnectResponse>*
RobotSessionServiceImpl::Connect(grpc::CallbackServerContext*) {
  return new SessionReactor(hub_);
}

}  // namespace semnav::reasoning
