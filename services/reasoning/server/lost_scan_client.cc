#include "services/reasoning/server/lost_scan_client.h"

#include <grpcpp/client_context.h>

#include <chrono>

#include "services/common/status/grpc_status.h"

namespace semnav::reasoning {

namespace mapping_api = ::semnav::mapping::v1;

MappingLostScanClient::MappingLostScanClient(std::shared_ptr<grpc::Channel> channel,
                                             int deadline_ms)
    : stub_(mapping_api::MappingService::NewStub(channel)), deadline_ms_(deadline_ms) {}

void MappingLostScanClient::MatchLostScan(
    const std::string& robot_id, const std::optional<PlanarTransform>& coarse,
    std::function<void(absl::StatusOr<ScanRefinement>)> done) {
  struct Call {
    grpc::ClientContext context;
    mapping_api::MatchLostScanRequest request;
    mapping_api::MatchLostScanResponse response;
  };
  auto call = std::make_shared<Call>();
  call->request.set_robot_id(robot_id);
  if (coarse.has_value()) {
    call->request.mutable_coarse()->set_x(coarse->translation.x());
    call->request.mutable_coarse()->set_y(coarse->translation.y());
    call->request.mutable_coarse()->set_yaw(coarse->yaw);
  } else {
    call->request.set_global(true);
  }
  call->context.set_deadline(std::chrono::system_clock::now() +
                             std::chrono::milliseconds(deadline_ms_));
  stub_->async()->MatchLostScan(&call->context, &call->request, &call->response,
                                [call, done = std::move(done)](grpc::Status status) {
                                  if (!status.ok()) {
                                    done(FromGrpcStatus(status));
                                    return;
                                  }
                                  const mapping_api::MatchLostScanResponse& r = call->response;
                                  ScanRefinement refinement;
                                  refinement.map_from_reported.translation =
                                      Eigen::Vector3d(r.correction().x(), r.correction().y(), 0.0);
                                  refinement.map_from_reported.yaw = r.correction().yaw();
                                  refinement.refined = r.refined();
                                  refinement.score = r.score();
                                  refinement.coarse_score = r.coarse_score();
                                  refinement.runner_up_score = r.runner_up_score();
                                  refinement.ray_conflicts = r.ray_conflicts();
                                  done(refinement);
                                });
}

}  // namespace semnav::reasoning
