#include "clients/sim/loop/frame_stream.h"

#include "absl/strings/str_cat.h"

namespace semnav::sim::loop {

namespace mapping = semnav::mapping::v1;

FrameStream::FrameStream(const std::shared_ptr<grpc::Channel>& channel)
    : stub_(mapping::MappingService::NewStub(channel)), stream_(stub_->StreamFrames(&context_)) {}

FrameStream::~FrameStream() {
  stream_->WritesDone();
  stream_->Finish();
}

absl::StatusOr<mapping::FrameAck> FrameStream::Send(const mapping::SensorFrame& frame) {
  mapping::StreamFramesRequest request;
  *request.mutable_frame() = frame;
  mapping::StreamFramesResponse response;
  if (!stream_->Write(request) || !stream_->Read(&response)) {
    return absl::UnavailableError("mapping closed the frame stream");
  }
  if (!response.ack().accepted()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "frame rejected: ", response.ack().error().reason(), " ", response.ack().error().field()));
  }
  return response.ack();
}

}  // namespace semnav::sim::loop
