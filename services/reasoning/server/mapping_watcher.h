// Follows mapping's WatchSceneGraph in a background thread and hands every new revision to a
// callback; reconnects (from the mirrored revision) after errors with a 1 s pause.
#pragma once

#include <functional>
#include <memory>
#include <thread>

#include <grpcpp/channel.h>
#include <grpcpp/client_context.h>

#include "absl/synchronization/mutex.h"
#include "services/reasoning/core/scene_graph.h"
#include "services/reasoning/server/scene_graph_mirror.h"

namespace semnav::reasoning {

class MappingWatcher {
 public:
  MappingWatcher(std::shared_ptr<grpc::Channel> channel, std::function<void(const SceneGraph&)> on_graph);
  ~MappingWatcher();  // Stop()
  void Stop();

 private:
  void Run();

  std::shared_ptr<grpc::Channel> channel_;
  std::function<void(const SceneGraph&)> on_graph_;
  absl::Mutex mu_;
  bool stopping_ ABSL_GUARDED_BY(mu_) = false;
  grpc::ClientContext* active_ ABSL_GUARDED_BY(mu_) = nullptr;
  std::thread thread_;
};

}  // namespace semnav::reasoning
