#include "services/mapping/landmarks/landmark_publisher.h"

#include <algorithm>
#include <chrono>

#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/common/status/field_error.h"
#include "services/relocalization/core/landmark_store.h"
#include "services/relocalization/server/proto_convert.h"

namespace semnav::mapping {
namespace {

namespace rv1 = semnav::relocalization::v1;

void SetDeadline(grpc::ClientContext& context, int deadline_ms) {
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::milliseconds(deadline_ms));
}

}  // namespace

absl::Status ValidateLandmarkPublisherConfig(const LandmarkPublisherConfig& config) {
  if (absl::Status s = relocalization::ValidateMapId(config.live_map_id); !s.ok()) {
    return InvalidField("live_map_id", s.message());
  }
  if (!(config.interval_s >= 0.05 && config.interval_s <= 3600.0)) {
    return InvalidField("interval_s", "must be in [0.05, 3600]");
  }
  if (config.deadline_ms < 10 || config.deadline_ms > 600000) {
    return InvalidField("deadline_ms", "must be in [10, 600000]");
  }
  if (!(config.settle_s >= 0.0 && config.settle_s <= 600.0)) {
    return InvalidField("settle_s", "must be in [0, 600]");
  }
  return absl::OkStatus();
}

absl::StatusOr<std::unique_ptr<LandmarkPublisher>> LandmarkPublisher::Start(
    const MappingEngine& engine, const SceneLandmarkConfig& landmarks,
    const LandmarkPublisherConfig& config) {
  if (absl::Status s = ValidateSceneLandmarkConfig(landmarks); !s.ok()) return s;
  if (absl::Status s = ValidateLandmarkPublisherConfig(config); !s.ok()) return s;
  absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = MakeChannel(config.relocalization);
  if (!channel.ok()) return absl::FailedPreconditionError(channel.status().message());
  std::unique_ptr<LandmarkPublisher> publisher(
      new LandmarkPublisher(engine, landmarks, config, *std::move(channel)));
  publisher->thread_ = std::thread([raw = publisher.get()] { raw->Run(); });
  LogInfo("landmark_publisher_started",
          {{"relocalization", config.relocalization.address}, {"live_map_id", config.live_map_id}});
  return publisher;
}

LandmarkPublisher::LandmarkPublisher(const MappingEngine& engine,
                                     const SceneLandmarkConfig& landmarks,
                                     const LandmarkPublisherConfig& config,
                                     std::shared_ptr<grpc::Channel> channel)
    : engine_(engine),
      landmarks_(landmarks),
      config_(config),
      stub_(rv1::RelocalizationService::NewStub(std::move(channel))) {}

LandmarkPublisher::~LandmarkPublisher() { Stop(); }

void LandmarkPublisher::Stop() {
  {
    absl::MutexLock lock(&mu_);
    stopping_ = true;
  }
  if (thread_.joinable()) thread_.join();
}

void LandmarkPublisher::PublishSnapshot(const std::string& map_id,
                                        std::vector<relocalization::Landmark> landmarks) {
  absl::MutexLock lock(&mu_);
  snapshots_.push_back({map_id, std::move(landmarks)});
}

void LandmarkPublisher::SceneReplaced() {
  {
    absl::MutexLock lock(&mu_);
    scene_replaced_ = true;
  }
  if (config_.push_with_frames) SyncLive();
}

void LandmarkPublisher::FrameIntegrated() {
  if (config_.push_with_frames) SyncLive();
}

void LandmarkPublisher::SyncLive() {
  absl::MutexLock push(&push_mu_);
  bool replaced = false;
  {
    absl::MutexLock lock(&mu_);
    if (stopping_) return;
    replaced = scene_replaced_;
    scene_replaced_ = false;
  }
  // The live map started over (ResetMap, LoadMap): so does its landmark map, or landmarks of
  // the old scene (another building, for the simulator's next episode) would stay in it.
  if (replaced) {
    landmark_of_object_.clear();
    have_published_ = false;
    DeleteLiveMap();
  }
  PushLive();
}

void LandmarkPublisher::Run() {
  const absl::Duration interval = absl::Seconds(config_.interval_s);
  absl::MutexLock lock(&mu_);
  while (!stopping_) {
    auto wake = [this]()
                    ABSL_SHARED_LOCKS_REQUIRED(mu_) { return stopping_ || !snapshots_.empty(); };
    mu_.AwaitWithTimeout(absl::Condition(&wake), interval);
    if (stopping_) break;
    if (!snapshots_.empty()) {
      Snapshot next = std::move(snapshots_.front());
      snapshots_.pop_front();
      mu_.Unlock();  // remote calls never hold the lock
      {
        absl::MutexLock push(&push_mu_);
        PushSnapshot(next);
      }
      mu_.Lock();
      continue;
    }
    if (config_.push_with_frames) continue;  // the live map is pushed with the frames
    mu_.Unlock();
    SyncLive();
    mu_.Lock();
  }
}

void LandmarkPublisher::NoteResult(const grpc::Status& status, absl::string_view what) {
  const bool reachable = status.error_code() != grpc::StatusCode::UNAVAILABLE &&
                         status.error_code() != grpc::StatusCode::DEADLINE_EXCEEDED;
  if (reachable == reachable_ && status.ok()) return;
  if (!reachable && !reachable_) return;  // already said so
  reachable_ = reachable;
  if (status.ok()) {
    LogInfo("relocalization_reachable", {{"address", config_.relocalization.address}});
  } else if (!reachable) {
    LogWarning("relocalization_unreachable", {{"address", config_.relocalization.address},
                                              {"what", std::string(what)},
                                              {"message", status.error_message()}});
  } else {
    LogWarning("landmark_push_rejected",
               {{"what", std::string(what)}, {"message", status.error_message()}});
  }
}

void LandmarkPublisher::PushLive() {
  const SceneSnapshot scene = engine_.Scene();
  if (have_published_ && scene.revision == published_revision_) return;
  const std::vector<SceneLandmark> found =
      LandmarksFromScene(SettledInstances(scene.objects, config_.settle_s), landmarks_);
  if (found.empty()) return;
  rv1::UpsertLandmarksRequest request;
  request.set_map_id(config_.live_map_id);
  // Beyond the request limit (a very large map) the rest waits for the next interval.
  const size_t count = std::min(found.size(), relocalization::kMaxLandmarksPerRequest);
  for (size_t i = 0; i < count; ++i) {
    relocalization::Landmark l = found[i].landmark;
    const auto known = landmark_of_object_.find(found[i].object_id);
    l.id = known == landmark_of_object_.end() ? 0 : known->second;
    relocalization::LandmarkToProto(l, request.add_landmarks());
  }
  rv1::UpsertLandmarksResponse response;
  grpc::ClientContext context;
  SetDeadline(context, config_.deadline_ms);
  const grpc::Status status = stub_->UpsertLandmarks(&context, request, &response);
  NoteResult(status, config_.live_map_id);
  if (status.error_code() == grpc::StatusCode::NOT_FOUND) {
    // A landmark we replace is gone (relocalization restarted without storage, or the map was
    // deleted): insert everything afresh next time.
    landmark_of_object_.clear();
    return;
  }
  if (!status.ok()) return;
  for (size_t i = 0; i < count && i < static_cast<size_t>(response.landmark_ids_size()); ++i) {
    landmark_of_object_[found[i].object_id] = response.landmark_ids(static_cast<int>(i));
  }
  if (count == found.size()) {
    published_revision_ = scene.revision;
    have_published_ = true;
  }
}

void LandmarkPublisher::DeleteLiveMap() {
  rv1::DeleteLandmarkMapRequest request;
  request.set_map_id(config_.live_map_id);
  rv1::DeleteLandmarkMapResponse response;
  grpc::ClientContext context;
  SetDeadline(context, config_.deadline_ms);
  const grpc::Status status = stub_->DeleteLandmarkMap(&context, request, &response);
  if (!status.ok() && status.error_code() != grpc::StatusCode::NOT_FOUND)
    NoteResult(status, config_.live_map_id);
}

void LandmarkPublisher::PushSnapshot(const Snapshot& snapshot) {
  {
    rv1::DeleteLandmarkMapRequest request;
    request.set_map_id(snapshot.map_id);
    rv1::DeleteLandmarkMapResponse response;
    grpc::ClientContext context;
    SetDeadline(context, config_.deadline_ms);
    const grpc::Status status = stub_->DeleteLandmarkMap(&context, request, &response);
    if (!status.ok() && status.error_code() != grpc::StatusCode::NOT_FOUND) {
      NoteResult(status, snapshot.map_id);
      return;
    }
  }
  for (size_t first = 0; first < snapshot.landmarks.size();
       first += relocalization::kMaxLandmarksPerRequest) {
    rv1::UpsertLandmarksRequest request;
    request.set_map_id(snapshot.map_id);
    const size_t end =
        std::min(snapshot.landmarks.size(), first + relocalization::kMaxLandmarksPerRequest);
    for (size_t i = first; i < end; ++i) {
      relocalization::Landmark l = snapshot.landmarks[i];
      l.id = 0;  // a fresh map: inserted (or fused with a duplicate of the same object)
      relocalization::LandmarkToProto(l, request.add_landmarks());
    }
    rv1::UpsertLandmarksResponse response;
    grpc::ClientContext context;
    SetDeadline(context, config_.deadline_ms);
    const grpc::Status status = stub_->UpsertLandmarks(&context, request, &response);
    NoteResult(status, snapshot.map_id);
    if (!status.ok()) return;
  }
  LogInfo("landmark_map_published",
          {{"map_id", snapshot.map_id},
           {"landmarks", static_cast<int64_t>(snapshot.landmarks.size())}});
}

}  // namespace semnav::mapping
