#include "services/reasoning/server/mapping_watcher.h"

#include "absl/strings/str_cat.h"
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

void MappingWatcher::Deliver(const SceneGraph& graph, bool restart) {
  absl::MutexLock lock(&delivery_mu_);
  if (!restart && delivered_revision_.has_value() && graph.revision <= *delivered_revision_) return;
  delivered_revision_ = graph.revision;
  on_graph_(graph);
}

absl::Status MappingWatcher::CatchUp(absl::Duration timeout) {
  auto stub = mapping::v1::MappingService::NewStub(channel_);
  grpc::ClientContext context;
  context.set_deadline(absl::ToChronoTime(absl::Now() + timeout));
  // Lock step: a channel still connecting (mapping started after the gateway, or a reconnect
  // back-off) is waited for, so whether a step sees its frame never depends on wall time.
  context.set_wait_for_ready(true);
  mapping::v1::GetSceneGraphResponse response;
  const grpc::Status status =
      stub->GetSceneGraph(&context, mapping::v1::GetSceneGraphRequest(), &response);
  if (!status.ok())
    return absl::UnavailableError(absl::StrCat("mapping GetSceneGraph: ", status.error_message()));
  mapping::v1::WatchSceneGraphResponse snapshot;
  *snapshot.mutable_snapshot() = std::move(*response.mutable_graph());
  SceneGraphMirror fetched;
  fetched.Apply(snapshot);
  Deliver(fetched.graph(), /*restart=*/false);
  return absl::OkStatus();
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
      const bool restart = !delivered && update.has_snapshot();
      delivered = true;
      if (!mirror.Apply(update)) {
        context.TryCancel();  // gap: restart from a snapshot
        mirror = SceneGraphMirror();
        break;
      }
      Deliver(mirror.graph(), restart);
    }
    const grpc::Status status = reader->Finish();
    absl::MutexLock lock(&mu_);
    active_ = nullptr;
    if (stopping_) return;
    // Mapping not (yet) up is normal at start-up and while it restarts: retry quietly. A stream
    // that had delivered and then broke, or any other error, is worth a warning.
    const bool not_up = status.error_code() == grpc::StatusCode::UNAVAILABLE && !delivered;
    (not_up ? LogDebug : LogWarning)("mapping_watch_ended",
                                     {{"code", static_cast<int>(status.error_code())},
                                      {"message", status.error_message()},
                                      {"retry_s", 1}});
    mu_.AwaitWithTimeout(absl::Condition(&stopping_), absl::Seconds(1));
  }
}

}  // namespace semnav::reasoning
