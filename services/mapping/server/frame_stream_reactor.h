#pragma once

#include <grpcpp/grpcpp.h>

#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "services/mapping/core/mapping_engine.h"

namespace semnav::mapping {

// StreamFrames: read a frame, integrate it, write its ack, repeat until the client half-closes.
// A rejected frame is acknowledged with the error and the stream continues.
class FrameStreamReactor
    : public grpc::ServerBidiReactor<v1::StreamFramesRequest, v1::StreamFramesResponse> {
 public:
  explicit FrameStreamReactor(MappingEngine& engine);

  void OnReadDone(bool ok) override;
  void OnWriteDone(bool ok) override;
  void OnDone() override { delete this; }

 private:
  MappingEngine& engine_;
  v1::StreamFramesRequest request_;
  v1::StreamFramesResponse response_;
  uint64_t sequence_ = 0;
};

}  // namespace semnav::mapping
