#pragma once
// gRPC adapter of semnav.relocalization.v1.RelocalizationService (callback API). Calls run
// inline on gRPC's callback threads: a relocalization takes milliseconds, and every
// read works on an immutable map snapshot, so nothing blocks other calls for long.
#include <memory>

#include "absl/base/thread_annotations.h"
#include "absl/synchronization/mutex.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"
#include "services/common/idempotency/first_answer_cache.h"
#include "services/relocalization/core/landmark_store.h"
#include "services/relocalization/core/onnx_heads.h"
#include "services/relocalization/server/service_config.h"

namespace semnav::relocalization {

class RelocalizationServiceImpl final : public v1::RelocalizationService::CallbackService {
 public:
  // `detector` may be null (image input then answers FAILED_PRECONDITION).
  RelocalizationServiceImpl(const ServiceConfig& config, std::unique_ptr<LandmarkStore> store,
                            std::unique_ptr<OnnxHeads> detector);

  grpc::ServerUnaryReactor* ExtractObjectPoints(grpc::CallbackServerContext* context,
                                                const v1::ExtractObjectPointsRequest* request,
                                                v1::ExtractObjectPointsResponse* response) override;
  grpc::ServerUnaryReactor* UpsertLandmarks(grpc::CallbackServerContext* context,
                                            const v1::UpsertLandmarksRequest* request,
                                            v1::UpsertLandmarksResponse* response) override;
  grpc::ServerWriteReactor<v1::GetLandmarkMapResponse>* GetLandmarkMap(
      grpc::CallbackServerContext* context, const v1::GetLandmarkMapRequest* request) override;
  grpc::ServerUnaryReactor* DeleteLandmarkMap(grpc::CallbackServerContext* context,
                                              const v1::DeleteLandmarkMapRequest* request,
                                              v1::DeleteLandmarkMapResponse* response) override;
  grpc::ServerUnaryReactor* Relocalize(grpc::CallbackServerContext* context,
                                       const v1::RelocalizeRequest* request,
                                       v1::RelocalizeResponse* response) override;
  grpc::ServerUnaryReactor* AlignMaps(grpc::CallbackServerContext* context,
                                      const v1::AlignMapsRequest* request,
                                      v1::AlignMapsResponse* response) override;

 private:
  absl::Status DoExtract(const v1::ExtractObjectPointsRequest& request,
                         v1::ExtractObjectPointsResponse& response);
  absl::Status DoUpsert(const v1::UpsertLandmarksRequest& request,
                        v1::UpsertLandmarksResponse& response);
  absl::Status DoDelete(const v1::DeleteLandmarkMapRequest& request);
  absl::Status DoRelocalize(const v1::RelocalizeRequest& request, v1::RelocalizeResponse& response);
  absl::Status DoAlign(const v1::AlignMapsRequest& request, v1::AlignMapsResponse& response);
  // The map snapshot, or NOT_FOUND / DATA_LOSS / INVALID_ARGUMENT naming `field`.
  absl::StatusOr<std::shared_ptr<const LandmarkMap>> GetMap(const std::string& map_id,
                                                            absl::string_view field) const;

  const ServiceConfig config_;
  const std::unique_ptr<LandmarkStore> store_;
  const std::unique_ptr<OnnxHeads> detector_;
  absl::Mutex transaction_mu_;  // upserts/deletes: idempotency check + apply + remember
  FirstAnswerCache<v1::UpsertLandmarksResponse> upsert_answers_ ABSL_GUARDED_BY(transaction_mu_);
  FirstAnswerCache<v1::DeleteLandmarkMapResponse> delete_answers_ ABSL_GUARDED_BY(transaction_mu_);
};

}  // namespace semnav::relocalization
