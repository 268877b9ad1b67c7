#pragma once

#include <grpcpp/grpcpp.h>

#include <atomic>
#include <memory>

#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "services/common/idempotency/first_answer_cache.h"
#include "services/common/server/worker_pool.h"
#include "services/mapping/core/map_store.h"
#include "services/mapping/core/mapping_engine.h"
#include "services/mapping/landmarks/landmark_publisher.h"
#include "services/mapping/server/live_snapshot.h"
#include "services/mapping/server/mapping_config_yaml.h"

namespace semnav::mapping {

// semnav.mapping.v1.MappingService over one MappingEngine and one MapStore (callback API).
class MappingServiceImpl final : public v1::MappingService::CallbackService {
 public:
  MappingServiceImpl(const MappingServiceConfig& config, MapStore store);

  // Restores the live map a crashed predecessor left and snapshots it from now on
  // (config live_snapshot_interval_s; 0 = off).
  absl::Status StartLiveSnapshots();
  // Pushes the scene graph's landmarks to the relocalization service configured in
  // landmarks.relocalization.address (no-op when empty).
  absl::Status StartLandmarkPublisher();
  // Server shutdown hook: ends every watch stream; a clean stop discards the live snapshot.
  void Shutdown();

  grpc::ServerBidiReactor<v1::StreamFramesRequest, v1::StreamFramesResponse>* StreamFrames(
      grpc::CallbackServerContext* context) override;
  grpc::ServerUnaryReactor* GetGridMap(grpc::CallbackServerContext* context,
                                       const v1::GetGridMapRequest* request,
                                       v1::GetGridMapResponse* response) override;
  grpc::ServerWriteReactor<v1::WatchGridMapResponse>* WatchGridMap(
      grpc::CallbackServerContext* context, const v1::WatchGridMapRequest* request) override;
  grpc::ServerWriteReactor<v1::GetOccupancyResponse>* GetOccupancy(
      grpc::CallbackServerContext* context, const v1::GetOccupancyRequest* request) override;
  grpc::ServerUnaryReactor* GetSceneGraph(grpc::CallbackServerContext* context,
                                          const v1::GetSceneGraphRequest* request,
                                          v1::GetSceneGraphResponse* response) override;
  grpc::ServerWriteReactor<v1::WatchSceneGraphResponse>* WatchSceneGraph(
      grpc::CallbackServerContext* context, const v1::WatchSceneGraphRequest* request) override;
  grpc::ServerUnaryReactor* QueryObjects(grpc::CallbackServerContext* context,
                                         const v1::QueryObjectsRequest* request,
                                         v1::QueryObjectsResponse* response) override;
  grpc::ServerUnaryReactor* SaveMap(grpc::CallbackServerContext* context,
                                    const v1::SaveMapRequest* request,
                                    v1::SaveMapResponse* response) override;
  grpc::ServerUnaryReactor* LoadMap(grpc::CallbackServerContext* context,
                                    const v1::LoadMapRequest* request,
                                    v1::LoadMapResponse* response) override;
  grpc::ServerUnaryReactor* ListMaps(grpc::CallbackServerContext* context,
                                     const v1::ListMapsRequest* request,
                                     v1::ListMapsResponse* response) override;
  grpc::ServerUnaryReactor* DeleteMap(grpc::CallbackServerContext* context,
                                      const v1::DeleteMapRequest* request,
                                      v1::DeleteMapResponse* response) override;
  grpc::ServerUnaryReactor* ResetMap(grpc::CallbackServerContext* context,
                                     const v1::ResetMapRequest* request,
                                     v1::ResetMapResponse* response) override;
  grpc::ServerUnaryReactor* MatchLostScan(grpc::CallbackServerContext* context,
                                          const v1::MatchLostScanRequest* request,
                                          v1::MatchLostScanResponse* response) override;

 private:
  // Runs `call` once per (method, request_id) and replays its answer for repeats.
  template <typename Response, typename Call>
  grpc::Status Idempotent(const std::string& method, const std::string& request_id,
                          Response* response, Call call);

  // After LoadMap: hands the map's saved landmarks (or its scene graph's) to relocalization.
  void PublishLoadedLandmarks(const std::string& map_id);
  // A transactional call's first answer: its status and, when OK, the serialized response.
  struct IdempotentAnswer {
    grpc::Status status;
    std::string response;
  };

  MappingServiceConfig config_;
  MapStore store_;
  MappingEngine engine_;
  FirstAnswerCache<IdempotentAnswer> idempotency_;  // by "<method>/<request_id>", under store_mu_
  absl::Mutex store_mu_;                            // one save/load/delete at a time
  std::atomic<bool> stopping_{false};
  std::unique_ptr<LiveSnapshot> live_snapshot_;
  std::unique_ptr<LandmarkPublisher> landmark_publisher_;  // null without a relocalization service
  // Last: destroyed first, so the frames it still holds integrate into a live engine.
  WorkerPool integration_;
};

}  // namespace semnav::mapping
