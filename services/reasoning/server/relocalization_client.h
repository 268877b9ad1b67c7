// The gateway's thin adapter to the relocalization service (seed 001): the loop's observed
// objects become RelocalizeRequest.observed landmarks, the pose solution becomes the loop's
// map -> odom answer. Calls run asynchronously (gRPC callback API); `done` runs on gRPC's thread.
#pragma once

#include <grpcpp/channel.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"
#include "services/reasoning/core/relocalization_loop.h"

namespace semnav::reasoning {

class Relocalizer {
 public:
  virtual ~Relocalizer() = default;
  // map_from_odom of `observed` (odometry frame) in landmark map `map_id`.
  virtual void Relocalize(const std::string& map_id, const std::vector<ObservedObject>& observed,
                          std::function<void(absl::StatusOr<RelocalizationAnswer>)> done) = 0;
};

// Request and answer conversions, shared by the client and its tests.
semnav::relocalization::v1::RelocalizeRequest ToRelocalizeRequest(
    const std::string& map_id, const std::vector<ObservedObject>& observed);
RelocalizationAnswer FromRelocalizeResponse(
    const semnav::relocalization::v1::RelocalizeResponse& response);

class RelocalizationClient : public Relocalizer {
 public:
  RelocalizationClient(std::shared_ptr<grpc::Channel> channel, int deadline_ms);
  void Relocalize(const std::string& map_id, const std::vector<ObservedObject>& observed,
                  std::function<void(absl::StatusOr<RelocalizationAnswer>)> done) override;

 private:
  std::unique_ptr<semnav::relocalization::v1::RelocalizationService::Stub> stub_;
  int deadline_ms_;
};

}  // namespace semnav::reasoning
