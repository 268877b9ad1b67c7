// Follows mapping's WatchSceneGraph in a background thread and hands every new revision to a
// callback; reconnects (from the mirrored revision) after errors with a 1 s pause. CatchUp
// fetches the current graph at once for simulated-clock robots, which cannot wait for the watch.
// Revisions reach the callback in increasing order (a new snapshot after a reconnect excepted).
#pragma once

#include <grpcpp/channel.h>
#include <grpcpp/client_context.h>

#include <functional>
#include <memory>
#include <optional>
#include <thread>

#include "absl/status/status.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "services/reasoning/core/scene_graph.h"
#include "services/reasoning/server/scene_graph_mirror.h"

namespace semnav::reasoning {

class MappingWatcher {
 public:
  MappingWatcher(std::shared_ptr<grpc::Channel> channel,
                 std::function<void(const SceneGraph&)> on_graph);
  ~MappingWatcher();  // Stop()
  void Stop();
  // GetSceneGraph within `timeout`; the graph goes to the callback (on the calling thread) when
  // it is newer than the last one delivered. UNAVAILABLE when mapping does not answer.
  absl::Status CatchUp(absl::Duration timeout);

 private:
  void Run();
  // Hands `graph` to the callback unless an equal or newer revision went first (`restart`: a
  // snapshot after a reconnect, always delivered).
  void Deliver(const SceneGraph& graph, bool restart) ABSL_LOCKS_EXCLUDED(delivery_mu_);

  std::shared_ptr<grpc::Channel> channel_;
  std::function<void(const SceneGraph&)> on_graph_;
  absl::Mutex mu_;
  bool stopping_ ABSL_GUARDED_BY(mu_) = false;
  grpc::ClientContext* active_ ABSL_GUARDED_BY(mu_) = nullptr;
  absl::Mutex delivery_mu_;  // one delivery at a time, in revision order
  std::optional<uint64_t> delivered_revision_ ABSL_GUARDED_BY(delivery_mu_);
  std::thread thread_;
};

}  // namespace semnav::reasoning
