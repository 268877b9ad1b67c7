// The robot's MappingService/StreamFrames client stream: one frame out, one ack back.
#pragma once

#include <grpcpp/grpcpp.h>

#include <memory>

#include "absl/status/statusor.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"

namespace semnav::sim::loop {

class FrameStream {
 public:
  explicit FrameStream(const std::shared_ptr<grpc::Channel>& mapping);
  ~FrameStream();
  // Sends a frame and waits for its ack; a rejected frame is an error naming the field.
  absl::StatusOr<semnav::mapping::v1::FrameAck> Send(const semnav::mapping::v1::SensorFrame& frame);

 private:
  grpc::ClientContext context_;
  std::unique_ptr<semnav::mapping::v1::MappingService::Stub> stub_;
  std::unique_ptr<grpc::ClientReaderWriter<semnav::mapping::v1::StreamFramesRequest,
                                           semnav::mapping::v1::StreamFramesResponse>>
      stream_;
};

}  // namespace semnav::sim::loop
