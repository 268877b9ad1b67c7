#include "services/reasoning/server/relocalization_client.h"

#include <grpcpp/client_context.h>

#include <chrono>

#include "services/common/status/grpc_status.h"
#include "services/reasoning/server/proto_convert.h"

namespace semnav::reasoning {

namespace reloc_api = ::semnav::relocalization::v1;

reloc_api::RelocalizeRequest ToRelocalizeRequest(const std::string& map_id,
                                                 const std::vector<ObservedObject>& observed) {
  reloc_api::RelocalizeRequest request;
  request.set_map_id(map_id);
  for (const ObservedObject& object : observed) {
    reloc_api::Landmark* landmark = request.add_observed();
    landmark->mutable_position()->set_x(object.position.x());
    landmark->mutable_position()->set_y(object.position.y());
    landmark->mutable_position()->set_z(object.position.z());
    landmark->set_scale_m(object.scale_m);
    landmark->mutable_embedding()->Assign(object.embedding.begin(), object.embedding.end());
    landmark->set_observations(static_cast<uint32_t>(object.observations));
  }
  return request;
}

RelocalizationAnswer FromRelocalizeResponse(const reloc_api::RelocalizeResponse& response) {
  const reloc_api::PoseSolution& solution = response.solution();
  const RobotPose pose = FromProto(solution.map_from_query());
  RelocalizationAnswer answer;
  answer.map_from_odom = PlanarTransform{pose.position, pose.yaw};
  answer.reliable = solution.reliable();
  answer.inliers = static_cast<int>(solution.inlier_count());
  answer.rms_residual_m = solution.rms_residual_m();
  return answer;
}

RelocalizationClient::RelocalizationClient(std::shared_ptr<grpc::Channel> channel, int deadline_ms)
    : stub_(reloc_api::RelocalizationService::NewStub(channel)), deadline_ms_(deadline_ms) {}

void RelocalizationClient::Relocalize(
    const std::string& map_id, const std::vector<ObservedObject>& observed,
    std::function<void(absl::StatusOr<RelocalizationAnswer>)> done) {
  struct Call {
    grpc::ClientContext context;
    reloc_api::RelocalizeRequest request;
    reloc_api::RelocalizeResponse response;
  };
  auto call = std::make_shared<Call>();
  call->request = ToRelocalizeRequest(map_id, observed);
  call->context.set_deadline(std::chrono::system_clock::now() +
                             std::chrono::milliseconds(deadline_ms_));
  stub_->async()->Relocalize(&call->context, &call->request, &call->response,
                             [call, done = std::move(done)](grpc::Status status) {
                               if (!status.ok()) {
                                 done(FromGrpcStatus(status));
                                 return;
                               }
                               done(FromRelocalizeResponse(call->response));
                             });
}

}  // namespace semnav::reasoning
