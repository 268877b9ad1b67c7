// Ctrl-C: while a stream is being followed it cancels that stream (the command detaches and
// exits normally); at any other time it ends the process with exit code 130.
#pragma once

#include <grpcpp/client_context.h>

namespace semnav::cli {

// Blocks SIGINT/SIGTERM in every thread and handles them on a dedicated one. Call first in main,
// before gRPC starts its threads.
void InstallInterruptHandler();

// While alive, an interrupt cancels `context` instead of ending the process.
class InterruptScope {
 public:
  explicit InterruptScope(grpc::ClientContext* context);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
  // True once an interrupt cancelled the scope's call.
  bool interrupted() const;
};

}  // namespace semnav::cli
