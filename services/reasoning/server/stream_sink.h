// Where the hub delivers stream messages (task snapshots, events, robot commands). Implemented by
// the gRPC reactors; called with the hub's lock held, so implementations only queue.
#pragma once

#include <grpcpp/support/status.h>

namespace semnav::reasoning {

template <typename Message>
class StreamSink {
 public:
  virtual ~StreamSink() = default;
  virtual void Send(const Message& message) = 0;
  // Ends the stream after the queued messages.
  virtual void Close(const grpc::Status& status) = 0;
};

}  // namespace semnav::reasoning
