// Mapping's client of the relocalization service: keeps the landmark map of the live scene graph
// (map id `live_map_id`) up to date, and hands saved/loaded maps' landmarks over under their map
// id. Pushes run on one background thread with a deadline: frame ingestion and map RPCs never
// wait for relocalization, and an absent relocalization service is logged, not fatal. A
// simulator in lock-step time pushes the live map with each frame instead (push_with_frames).
#pragma once

#include <grpcpp/channel.h>

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"
#include "services/common/client/channel.h"
#include "services/mapping/core/mapping_engine.h"
#include "services/mapping/landmarks/scene_landmarks.h"

namespace semnav::mapping {

struct LandmarkPublisherConfig {
  ClientOptions relocalization;      // address empty = no relocalization service (nothing pushed)
  std::string live_map_id = "live";  // landmark map of the live scene graph
  double interval_s = 2.0;           // debounce: at most one live push per interval
  int deadline_ms = 2000;            // per relocalization call
  // An instance reaches the live landmark map once it has not been observed for this long (scene
  // time): a robot's localizer reports a lost pose late (the simulator's model: 2.5 s), and the
  // instances its frames made meanwhile must not be in the map when the loss marks them
  // (SceneObject::pose_untrusted). 0 = at once.
  double settle_s = 2.5;
  // The live push runs with each frame, before its ack, and with ResetMap/LoadMap, instead of on
  // the background thread's interval: the live landmark map then follows the scene graph frame by
  // frame, so a lock-step simulated episode that relocalizes in it does not depend on when a
  // thread ran. A real robot's frames keep off (they would wait for relocalization).
  bool push_with_frames = false;
};

// INVALID_ARGUMENT naming live_map_id / interval_s / deadline_ms.
absl::Status ValidateLandmarkPublisherConfig(const LandmarkPublisherConfig& config);

class LandmarkPublisher {
 public:
  // Starts the background thread; FAILED_PRECONDITION when the channel cannot be made (bad TLS
  // files). `engine` must outlive the publisher.
  static absl::StatusOr<std::unique_ptr<LandmarkPublisher>> Start(
      const MappingEngine& engine, const SceneLandmarkConfig& landmarks,
      const LandmarkPublisherConfig& config);
  ~LandmarkPublisher();

  // Queues a whole landmark map to replace the relocalization service's map `map_id` (SaveMap,
  // LoadMap). Returns at once.
  void PublishSnapshot(const std::string& map_id, std::vector<relocalization::Landmark> landmarks);
  // The live scene graph was replaced (LoadMap, ResetMap): its instance ids start over, so the
  // live landmark map is deleted and its landmarks are inserted afresh (on the caller's thread
  // with push_with_frames).
  void SceneReplaced();
  // A frame was integrated. With push_with_frames the live push runs here, on the frame's
  // thread; otherwise nothing happens (the background thread pushes on its interval).
  void FrameIntegrated();
  void Stop();

 private:
  struct Snapshot {
    std::string map_id;
    std::vector<relocalization::Landmark> landmarks;
  };
  LandmarkPublisher(const MappingEngine& engine, const SceneLandmarkConfig& landmarks,
                    const LandmarkPublisherConfig& config, std::shared_ptr<grpc::Channel> channel);
  void Run();
  void SyncLive();  // the scene's replacement, if any, then the live push
  void PushLive() ABSL_EXCLUSIVE_LOCKS_REQUIRED(push_mu_);
  void DeleteLiveMap() ABSL_EXCLUSIVE_LOCKS_REQUIRED(push_mu_);  // after the scene was replaced
  void PushSnapshot(const Snapshot& snapshot) ABSL_EXCLUSIVE_LOCKS_REQUIRED(push_mu_);
  // Logs a change of reachability once (not every interval).
  void NoteResult(const grpc::Status& status, absl::string_view what)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(push_mu_);

  const MappingEngine& engine_;
  const SceneLandmarkConfig landmarks_;
  const LandmarkPublisherConfig config_;
  std::unique_ptr<relocalization::v1::RelocalizationService::Stub> stub_;
  std::thread thread_;

  mutable absl::Mutex mu_;
  bool stopping_ ABSL_GUARDED_BY(mu_) = false;
  std::deque<Snapshot> snapshots_ ABSL_GUARDED_BY(mu_);
  bool scene_replaced_ ABSL_GUARDED_BY(mu_) = false;

  // One push at a time: the background thread's, and with push_with_frames the frame threads'.
  // Never taken while holding mu_.
  absl::Mutex push_mu_;
  uint64_t published_revision_ ABSL_GUARDED_BY(push_mu_) = 0;
  bool have_published_ ABSL_GUARDED_BY(push_mu_) = false;
  // scene instance id -> landmark id
  std::map<uint64_t, uint64_t> landmark_of_object_ ABSL_GUARDED_BY(push_mu_);
  bool reachable_ ABSL_GUARDED_BY(push_mu_) = true;
};

}  // namespace semnav::mapping
