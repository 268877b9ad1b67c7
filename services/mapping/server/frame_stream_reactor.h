#pragma once

#include <grpcpp/grpcpp.h>

#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "services/common/server/worker_pool.h"
#include "services/mapping/core/mapping_engine.h"
#include "services/mapping/landmarks/landmark_publisher.h"

namespace semnav::mapping {

// StreamFrames: read a frame, integrate it, write its ack, repeat until the client half-closes.
// A rejected frame is acknowledged with the error and the stream continues. Frames integrate on
// `integration`, never on gRPC's callback threads: a frame costs tens of milliseconds, and a grid
// fetch queued behind it on a callback thread held up the commands waiting for that grid. The
// landmark publisher, if any, hears of each accepted frame before its ack (push_with_frames).
class FrameStreamReactor
    : public grpc::ServerBidiReactor<v1::StreamFramesRequest, v1::StreamFramesResponse> {
 public:
  // `landmarks` may be null (no relocalization service).
  FrameStreamReactor(MappingEngine& engine, WorkerPool& integration, LandmarkPublisher* landmarks);

  void OnReadDone(bool ok) override;
  void OnWriteDone(bool ok) override;
  void OnDone() override { delete this; }

 private:
  void Integrate();  // on an integration thread: the frame in request_, its ack written

  MappingEngine& engine_;
  WorkerPool& integration_;
  LandmarkPublisher* const landmarks_;
  v1::StreamFramesRequest request_;
  v1::StreamFramesResponse response_;
  uint64_t sequence_ = 0;
};

}  // namespace semnav::mapping
