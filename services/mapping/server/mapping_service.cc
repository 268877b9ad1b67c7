#include "services/mapping/server/mapping_service.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "services/common/crypto/sha256.h"
#include "services/common/logging/log.h"
#include "services/common/status/grpc_status.h"
#include "services/common/status/value_checks.h"
#include "services/mapping/core/window_validation.h"
#include "services/mapping/landmarks/saved_landmarks.h"
#include "services/mapping/server/frame_stream_reactor.h"
#include "services/mapping/server/proto_convert.h"
#include "services/mapping/server/watch_reactor.h"

namespace semnav::mapping {
namespace {

constexpr double kMaxOccupancyVoxels = 5e7;

grpc::Status Invalid(absl::string_view field, absl::string_view message) {
  return ToGrpcStatus(FieldError(absl::StatusCode::kInvalidArgument, field, message));
}

grpc::Status FromCore(const absl::Status& status) { return ToGrpcStatus(status); }

grpc::ServerUnaryReactor* Reply(grpc::CallbackServerContext* context, const grpc::Status& status) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(status);
  return reactor;
}

std::vector<semnav::common::v1::GridLayerKind> Kinds(
    const google::protobuf::RepeatedField<int>& kinds) {
  std::vector<semnav::common::v1::GridLayerKind> out;
  for (int k : kinds) out.push_back(static_cast<semnav::common::v1::GridLayerKind>(k));
  return out;
}

grpc::Status CheckWindow(const v1::Window& window, const MappingServiceConfig& config) {
  return FromCore(ValidateWindow(window.min().x(), window.min().y(), window.max().x(),
                                 window.max().y(), config.core.grid.resolution_m,
                                 config.window_limits));
}

GridWindow Intersect(const GridWindow& a, const GridWindow& b) {
  const int min_x = std::max(a.min.x, b.min.x);
  const int min_y = std::max(a.min.y, b.min.y);
  const int max_x = std::min(a.min.x + a.width, b.min.x + b.width);
  const int max_y = std::min(a.min.y + a.height, b.min.y + b.height);
  if (max_x <= min_x || max_y <= min_y) return {};
  return {{min_x, min_y}, max_x - min_x, max_y - min_y};
}

void InfoToProto(const StoredMap& info, v1::MapInfo* proto) {
  proto->set_map_id(info.map_id);
  proto->set_size_bytes(info.size_bytes);
  proto->set_saved_ns(info.saved_ns);
}

// Streams a prepared payload as DataChunks.
class ChunkWriter : public grpc::ServerWriteReactor<v1::GetOccupancyResponse> {
 public:
  ChunkWriter(std::string payload, std::string content_type, size_t chunk_bytes)
      : payload_(std::move(payload)),
        content_type_(std::move(content_type)),
        sha256_(Sha256Hex(payload_)),
        chunk_bytes_(chunk_bytes) {
    WriteNext();
  }
  void OnWriteDone(bool ok) override {
    if (!ok) {
      Finish(grpc::Status(grpc::StatusCode::CANCELLED, "client went away"));
      return;
    }
    WriteNext();
  }
  void OnDone() override { delete this; }

 private:
  void WriteNext() {
    if (offset_ >= payload_.size() && offset_ != 0) {
      Finish(grpc::Status::OK);
      return;
    }
    response_.Clear();
    auto* chunk = response_.mutable_chunk();
    chunk->set_offset(offset_);
    chunk->set_total_size(payload_.size());
    chunk->set_data(payload_.substr(offset_, chunk_bytes_));
    if (offset_ == 0) chunk->set_content_type(content_type_);
    offset_ += std::max<size_t>(chunk->data().size(), 1);
    if (offset_ >= payload_.size()) chunk->set_sha256(sha256_);
    StartWrite(&response_);
  }

  std::string payload_;
  std::string content_type_;
  std::string sha256_;
  size_t chunk_bytes_;
  size_t offset_ = 0;
  v1::GetOccupancyResponse response_;
};

template <typename Response>
grpc::ServerWriteReactor<Response>* FailStream(const grpc::Status& status) {
  class Failed : public grpc::ServerWriteReactor<Response> {
   public:
    explicit Failed(const grpc::Status& s) { this->Finish(s); }
    void OnDone() override { delete this; }
  };
  return new Failed(status);
}

}  // namespace

MappingServiceImpl::MappingServiceImpl(const MappingServiceConfig& config, MapStore store)
    : config_(config),
      store_(std::move(store)),
      engine_(config.core),
      idempotency_(config.idempotency_cache_size),
      integration_(config.integration_threads, config.integration_nice) {}

absl::Status MappingServiceImpl::StartLiveSnapshots() {
  if (config_.live_snapshot_interval_s <= 0) return absl::OkStatus();
  absl::StatusOr<std::unique_ptr<LiveSnapshot>> started = LiveSnapshot::Start(
      engine_, config_.store_directory, absl::Seconds(config_.live_snapshot_interval_s));
  if (!started.ok()) return started.status();
  live_snapshot_ = *std::move(started);
  return absl::OkStatus();
}

absl::Status MappingServiceImpl::StartLandmarkPublisher() {
  if (config_.landmark_publisher.relocalization.address.empty()) return absl::OkStatus();
  absl::StatusOr<std::unique_ptr<LandmarkPublisher>> started =
      LandmarkPublisher::Start(engine_, config_.landmarks, config_.landmark_publisher);
  if (!started.ok()) return started.status();
  landmark_publisher_ = *std::move(started);
  return absl::OkStatus();
}

void MappingServiceImpl::Shutdown() {
  stopping_.store(true);
  if (landmark_publisher_ != nullptr) landmark_publisher_->Stop();
  if (live_snapshot_ != nullptr) live_snapshot_->StopAndDiscard();
}

template <typename Response, typename Call>
grpc::Status MappingServiceImpl::Idempotent(const std::string& method,
                                            const std::string& request_id, Response* response,
                                            Call call) {
  if (request_id.empty()) return Invalid("request_id", "required for this call (idempotency key)");
  // Kept in the idempotency cache: a huge key would be held for the cache's lifetime.
  if (absl::Status s = CheckLength(request_id, "request_id", kMaxIdBytes); !s.ok()) {
    return ToGrpcStatus(s);
  }
  absl::MutexLock lock(&store_mu_);
  const std::string key = absl::StrCat(method, "/", request_id);
  if (std::optional<IdempotentAnswer> answer = idempotency_.Find(key)) {
    if (answer->status.ok()) response->ParseFromString(answer->response);
    return answer->status;
  }
  const grpc::Status status = call();
  idempotency_.Remember(key, {status, status.ok() ? response->SerializeAsString() : std::string()});
  return status;
}

grpc::ServerBidiReactor<v1::StreamFramesRequest, v1::StreamFramesResponse>*
MappingServiceImpl::StreamFrames(grpc::CallbackServerContext*) {
  return new FrameStreamReactor(engine_, integration_, landmark_publisher_.get());
}

grpc::ServerUnaryReactor* MappingServiceImpl::GetGridMap(grpc::CallbackServerContext* context,
                                                         const v1::GetGridMapRequest* request,
                                                         v1::GetGridMapResponse* response) {
  if (absl::Status s = CheckLayerKinds(request->layers(), "layers"); !s.ok())
    return Reply(context, FromCore(s));
  std::optional<GridWindow> window;
  if (request->has_window()) {
    if (grpc::Status s = CheckWindow(request->window(), config_); !s.ok()) return Reply(context, s);
    const auto& w = request->window();
    window = engine_.WindowOf(w.min().x(), w.min().y(), w.max().x(), w.max().y());
  }
  uint64_t revision = 0;
  const bool with_semantic =
      request->layers().empty() ||
      std::find(request->layers().begin(), request->layers().end(),
                semnav::common::v1::GRID_LAYER_KIND_SEMANTIC) != request->layers().end();
  const GridLayers layers = engine_.Grid(window, &revision, with_semantic);
  *response->mutable_grid() = GridToProto(layers, revision, Kinds(request->layers()));
  return Reply(context, grpc::Status::OK);
}

grpc::ServerWriteReactor<v1::WatchGridMapResponse>* MappingServiceImpl::WatchGridMap(
    grpc::CallbackServerContext*, const v1::WatchGridMapRequest* request) {
  if (absl::Status s = CheckLayerKinds(request->layers(), "layers"); !s.ok()) {
    return FailStream<v1::WatchGridMapResponse>(FromCore(s));
  }
  std::optional<GridWindow> watched;
  if (request->has_window()) {
    if (grpc::Status s = CheckWindow(request->window(), config_); !s.ok())
      return FailStream<v1::WatchGridMapResponse>(s);
    const auto& w = request->window();
    watched = engine_.WindowOf(w.min().x(), w.min().y(), w.max().x(), w.max().y());
  }
  const auto kinds = Kinds(request->layers());
  const absl::Duration interval = absl::Milliseconds(
      std::max<int>(config_.watch_min_interval_ms, static_cast<int>(request->min_interval_ms())));
  MappingEngine& engine = engine_;
  auto next = [&engine, watched, kinds](uint64_t last, bool first,
                                        v1::WatchGridMapResponse* out) -> std::optional<uint64_t> {
    const uint64_t now = engine.revision();
    std::optional<GridWindow> changed =
        (first && last == 0) ? std::nullopt : engine.GridChangesSince(last);
    const bool snapshot = !changed.has_value();
    std::optional<GridWindow> window = watched;
    if (!snapshot) {
      if (changed->width == 0) return std::nullopt;
      window = watched ? Intersect(*watched, *changed) : *changed;
      if (window->width == 0) return std::nullopt;
    }
    uint64_t revision = 0;
    const GridLayers layers = engine.Grid(window, &revision);
    *out->mutable_grid() = GridToProto(layers, revision, kinds);
    out->set_snapshot(snapshot);
    return std::max(revision, now);
  };
  return new WatchReactor<v1::WatchGridMapResponse>(engine_, stopping_, interval,
                                                    request->since_revision(), next);
}

grpc::ServerWriteReactor<v1::GetOccupancyResponse>* MappingServiceImpl::GetOccupancy(
    grpc::CallbackServerContext*, const v1::GetOccupancyRequest* request) {
  const Eigen::Vector3d min(request->min().x(), request->min().y(), request->min().z());
  const Eigen::Vector3d max(request->max().x(), request->max().y(), request->max().z());
  const double box_min[3] = {min.x(), min.y(), min.z()};
  const double box_max[3] = {max.x(), max.y(), max.z()};
  if (absl::Status s = ValidateOccupancyBox(box_min, box_max, config_.core.octomap_resolution_m,
                                            kMaxOccupancyVoxels, config_.window_limits);
      !s.ok()) {
    return FailStream<v1::GetOccupancyResponse>(FromCore(s));
  }
  return new ChunkWriter(engine_.OccupancyBinary(min, max), "application/x-octomap-bt",
                         static_cast<size_t>(config_.occupancy_chunk_bytes));
}

grpc::ServerUnaryReactor* MappingServiceImpl::GetSceneGraph(grpc::CallbackServerContext* context,
                                                            const v1::GetSceneGraphRequest*,
                                                            v1::GetSceneGraphResponse* response) {
  SceneToProto(engine_.Scene(), response->mutable_graph());
  return Reply(context, grpc::Status::OK);
}

grpc::ServerWriteReactor<v1::WatchSceneGraphResponse>* MappingServiceImpl::WatchSceneGraph(
    grpc::CallbackServerContext*, const v1::WatchSceneGraphRequest* request) {
  MappingEngine& engine = engine_;
  auto next = [&engine](uint64_t last, bool first,
                        v1::WatchSceneGraphResponse* out) -> std::optional<uint64_t> {
    const SceneSnapshot scene = engine.Scene();
    if (!first && scene.revision <= last) return std::nullopt;
    const std::optional<SceneDelta> delta =
        (first && last == 0) ? std::nullopt : engine.SceneChangesSince(last);
    if (!delta.has_value()) {
      SceneToProto(scene, out->mutable_snapshot());
      return scene.revision;
    }
    if (scene.revision <= last)
      return std::nullopt;  // resumed at the current revision: nothing to send
    v1::SceneGraph full;
    SceneToProto(scene, &full);
    v1::SceneGraphDelta* d = out->mutable_delta();
    d->set_from_revision(last);
    d->set_revision(scene.revision);
    for (const SceneObject& o : scene.objects) {
      if (std::find(delta->upserted_ids.begin(), delta->upserted_ids.end(), o.id) !=
          delta->upserted_ids.end()) {
        ObjectToProto(o, d->add_upserted_objects());
      }
    }
    d->mutable_removed_object_ids()->Assign(delta->removed_ids.begin(), delta->removed_ids.end());
    *d->mutable_relations() = full.relations();
    *d->mutable_regions() = full.regions();
    d->set_summary(full.summary());
    return scene.revision;
  };
  return new WatchReactor<v1::WatchSceneGraphResponse>(
      engine_, stopping_, absl::Milliseconds(config_.watch_min_interval_ms),
      request->since_revision(), next);
}

grpc::ServerUnaryReactor* MappingServiceImpl::QueryObjects(grpc::CallbackServerContext* context,
                                                           const v1::QueryObjectsRequest* request,
                                                           v1::QueryObjectsResponse* response) {
  ObjectQuery query;
  query.labels.assign(request->labels().begin(), request->labels().end());
  query.embedding.assign(request->embedding().begin(), request->embedding().end());
  query.min_cosine =
      request->min_cosine() == 0.0 ? config_.query_min_cosine : request->min_cosine();
  if (request->has_near())
    query.near = Eigen::Vector3d(request->near().x(), request->near().y(), request->near().z());
  query.near_radius_m = request->near_radius();
  query.max_results = request->max_results();
  const absl::StatusOr<std::vector<ObjectHit>> hits = engine_.QueryObjects(query);
  if (!hits.ok()) return Reply(context, FromCore(hits.status()));
  for (const ObjectHit& hit : *hits) {
    v1::ObjectMatch* match = response->add_matches();
    ObjectToProto(hit.object, match->mutable_object());
    match->set_cosine(hit.cosine);
    match->set_distance(hit.distance);
  }
  response->set_revision(engine_.Scene().revision);
  return Reply(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* MappingServiceImpl::SaveMap(grpc::CallbackServerContext* context,
                                                      const v1::SaveMapRequest* request,
                                                      v1::SaveMapResponse* response) {
  return Reply(
      context, Idempotent("SaveMap", request->request_id(), response, [&] {
        if (absl::Status s = MapStore::ValidateMapId(request->map_id()); !s.ok())
          return FromCore(s);
        // The landmarks first: a saved occupancy map always has its landmark map.
        const std::vector<SceneLandmark> landmarks =
            LandmarksFromScene(engine_.Scene().objects, config_.landmarks);
        if (absl::Status s = SaveLandmarks(config_.store_directory, request->map_id(), landmarks);
            !s.ok()) {
          return FromCore(s);
        }
        absl::StatusOr<StoredMap> saved = store_.Save(request->map_id(), engine_.Serialize());
        if (!saved.ok()) return FromCore(saved.status());
        if (landmark_publisher_ != nullptr) {
          std::vector<relocalization::Landmark> pushed;
          for (const SceneLandmark& l : landmarks) pushed.push_back(l.landmark);
          landmark_publisher_->PublishSnapshot(request->map_id(), std::move(pushed));
        }
        InfoToProto(*saved, response->mutable_map());
        return grpc::Status::OK;
      }));
}

void MappingServiceImpl::PublishLoadedLandmarks(const std::string& map_id) {
  if (landmark_publisher_ == nullptr) return;
  landmark_publisher_->SceneReplaced();
  std::vector<relocalization::Landmark> landmarks;
  absl::StatusOr<relocalization::LandmarkMap> saved =
      LoadLandmarks(config_.store_directory, map_id);
  if (saved.ok()) {
    landmarks = saved->landmarks();
  } else {
    // Saved before landmark maps existed, or the file is damaged: the restored scene graph
    // holds the same instances, so its landmarks are the ones SaveMap would have written.
    if (!absl::IsNotFound(saved.status())) {
      LogWarning("saved_landmarks_unreadable",
                 {{"map_id", map_id}, {"message", saved.status().message()}});
    }
    for (SceneLandmark& l : LandmarksFromScene(engine_.Scene().objects, config_.landmarks)) {
      landmarks.push_back(std::move(l.landmark));
    }
  }
  landmark_publisher_->PublishSnapshot(map_id, std::move(landmarks));
}

grpc::ServerUnaryReactor* MappingServiceImpl::LoadMap(grpc::CallbackServerContext* context,
                                                      const v1::LoadMapRequest* request,
                                                      v1::LoadMapResponse* response) {
  return Reply(context, Idempotent("LoadMap", request->request_id(), response, [&] {
                 absl::StatusOr<std::string> payload = store_.Load(request->map_id());
                 if (!payload.ok()) return FromCore(payload.status());
                 if (absl::Status restored = engine_.Restore(*payload); !restored.ok()) {
                   return FromCore(
                       absl::Status(restored.code(), absl::StrCat("map_id: ", restored.message())));
                 }
                 PublishLoadedLandmarks(request->map_id());
                 absl::StatusOr<StoredMap> info = store_.Stat(request->map_id());
                 if (info.ok()) InfoToProto(*info, response->mutable_map());
                 response->set_revision(engine_.revision());
                 return grpc::Status::OK;
               }));
}

grpc::ServerUnaryReactor* MappingServiceImpl::ListMaps(grpc::CallbackServerContext* context,
                                                       const v1::ListMapsRequest*,
                                                       v1::ListMapsResponse* response) {
  const absl::StatusOr<std::vector<StoredMap>> maps = store_.List();
  if (!maps.ok()) return Reply(context, FromCore(maps.status()));
  for (const StoredMap& info : *maps) InfoToProto(info, response->add_maps());
  return Reply(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* MappingServiceImpl::DeleteMap(grpc::CallbackServerContext* context,
                                                        const v1::DeleteMapRequest* request,
                                                        v1::DeleteMapResponse* response) {
  return Reply(context, Idempotent("DeleteMap", request->request_id(), response, [&] {
                 const absl::Status deleted = store_.Delete(request->map_id());
                 if (!deleted.ok()) return FromCore(deleted);
                 return FromCore(DeleteLandmarks(config_.store_directory, request->map_id()));
               }));
}

grpc::ServerUnaryReactor* MappingServiceImpl::ResetMap(grpc::CallbackServerContext* context,
                                                       const v1::ResetMapRequest* request,
                                                       v1::ResetMapResponse* response) {
  return Reply(context, Idempotent("ResetMap", request->request_id(), response, [&] {
                 engine_.Reset();
                 if (landmark_publisher_ != nullptr) landmark_publisher_->SceneReplaced();
                 response->set_revision(engine_.revision());
                 return grpc::Status::OK;
               }));
}

grpc::ServerUnaryReactor* MappingServiceImpl::MatchLostScan(grpc::CallbackServerContext* context,
                                                            const v1::MatchLostScanRequest* request,
                                                            v1::MatchLostScanResponse* response) {
  std::optional<PlanarCorrection> coarse;
  if (!request->global()) {
    coarse =
        PlanarCorrection{request->coarse().x(), request->coarse().y(), request->coarse().yaw()};
  }
  const absl::StatusOr<ScanMatchResult> match = engine_.MatchLostScan(request->robot_id(), coarse);
  if (!match.ok()) return Reply(context, FromCore(match.status()));
  response->mutable_correction()->set_x(match->correction.x);
  response->mutable_correction()->set_y(match->correction.y);
  response->mutable_correction()->set_yaw(match->correction.yaw);
  response->set_refined(match->refined);
  response->set_score(match->score);
  response->set_coarse_score(match->coarse_score);
  response->set_scan_cells(static_cast<uint32_t>(match->scan_cells));
  response->set_runner_up_score(match->runner_up_score);
  response->set_ray_conflicts(match->ray_conflicts);
  return Reply(context, grpc::Status::OK);
}

}  // namespace semnav::mapping
