#include "services/reasoning/server/mapping_watcher.h"

#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "services/common/logging/log.h"

namespace semnav::reasoning {

MappingWatcher::MappingWatcher(std::shared_ptr<grpc::Channel> channel,
                               std::function<void(const SceneGraph&)> on_graph)
    : channel_(std::move(channel)), on_graph_(std::move(on_graph)) {
  thread_ = std::thread([this] { Run(); });
}

MappingWatcher::~MappingWatcher() { Stop(); }

void MappingWatcher::Stop() {
  {
    absl::MutexLock lock(&mu_);
    stopping_ = true;
    if (active_ != nullptr) active_->TryCancel();
  }
  if (thread_.joinable()) thread_.join();
}

void MappingWatcher::Run() {
  auto stub = mapping::v1::MappingService::NewStub(channel_);
  SceneGraphMirror mirror;
  while (true) {
    grpc::ClientContext context;
    {
      absl::MutexLock lock(&mu_);
      if (stopping_) return;
      active_ = &context;
    }
    mapping::v1::WatchSceneGraphRequest request;
    request.set_since_revision(mirror.revision());
    auto reader = stub->WatchSceneGraph(&context, request);
    bool delivered = false;
    for (mapping::v1::WatchSceneGraphResponse update; reader->Read(&update);) {
      delivered = true;
      if (!mirror.Apply(update)) {
        context.TryCancel();  // gap: restart from a snapshot
        mirror = SceneGraphMirror();
        break;
      }
      on_graph_(mirror.graph());
    }
    const grpc::Status status = reader->Finish();
    absl::MutexLock lock(&mu_);
    active_ = nullptr;
    if (stopping_) return;
    // Mapping not (yet) up is normal at start-up and while it restarts: retry quietly. A stream
    // that had delivered and then broke, or any other error, is worth a warning.
    const bool not_up = status.error_code() == grpc::StatusCode::UNAVAILABLE && !delivered;
    (not_up ? LogDebug : LogWarning)("mapping_watch_ended", {{"code", static_cast<int>(status.error_code())},
                                                             {"message", status.error_message()},
                                                             {"retry_s", 1}});
    mu_.AwaitWithTimeout(absl::Condition(&stopping_), absl::Seconds(1));
  }
}

}  // namespace semnav::reasoning
