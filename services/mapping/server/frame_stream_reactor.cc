#include "services/mapping/server/frame_stream_reactor.h"

#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/common/status/field_error.h"
#include "services/mapping/server/proto_convert.h"

namespace semnav::mapping {

FrameStreamReactor::FrameStreamReactor(MappingEngine& engine, WorkerPool& integration,
                                       LandmarkPublisher* landmarks)
    : engine_(engine), integration_(integration), landmarks_(landmarks) {
  StartRead(&request_);
}

void FrameStreamReactor::OnReadDone(bool ok) {
  if (!ok) {
    Finish(grpc::Status::OK);
    return;
  }
  // No operation is outstanding until Integrate writes, so the reactor lives until then.
  if (!integration_.Submit([this] { Integrate(); })) {
    Finish(grpc::Status(grpc::StatusCode::UNAVAILABLE, "the mapping service is stopping"));
  }
}

void FrameStreamReactor::Integrate() {
  response_.Clear();
  v1::FrameAck* ack = response_.mutable_ack();
  ack->set_sequence(sequence_++);
  absl::StatusOr<SensorFrame> frame = FrameFromProto(request_.frame());
  absl::StatusOr<FrameResult> result = frame.ok() ? engine_.AddFrame(*frame) : frame.status();
  if (result.ok()) {
    ack->set_accepted(true);
    ack->set_revision(result->revision);
    ack->set_voxels_updated(result->voxels_updated);
    ack->set_detections_used(result->detections_used);
    ack->set_blurred(result->blurred);
    if (landmarks_ != nullptr) landmarks_->FrameIntegrated();
  } else {
    const absl::string_view message = result.status().message();
    ack->set_accepted(false);
    ack->set_revision(engine_.revision());
    ack->mutable_error()->set_reason(absl::StatusCodeToString(result.status().code()));
    ack->mutable_error()->set_field(ErrorField(result.status()).value_or(""));
    (*ack->mutable_error()->mutable_metadata())["message"] = std::string(message);
    LogInfo("frame_rejected", {{"sequence", ack->sequence()}, {"error", message}});
  }
  StartWrite(&response_);
}

void FrameStreamReactor::OnWriteDone(bool ok) {
  if (!ok) {
    Finish(grpc::Status(grpc::StatusCode::CANCELLED, "client went away"));
    return;
  }
  StartRead(&request_);
}

}  // namespace semnav::mapping
