// The gateway's thin adapter to mapping's MatchLostScan: the relocalization loop's coarse
// correction (reported frame -> map) goes out, the scan-matched one comes back. Calls run
// asynchronously (gRPC callback API); `done` runs on gRPC's thread.
#pragma once

#include <grpcpp/channel.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "services/reasoning/core/relocalization_loop.h"

namespace semnav::reasoning {

class LostScanMatcher {
 public:
  virtual ~LostScanMatcher() = default;
  // Around `coarse` (reported frame -> map), or over the whole map without one.
  virtual void MatchLostScan(const std::string& robot_id,
                             const std::optional<PlanarTransform>& coarse,
                             std::function<void(absl::StatusOr<ScanRefinement>)> done) = 0;
};

class MappingLostScanClient : public LostScanMatcher {
 public:
  MappingLostScanClient(std::shared_ptr<grpc::Channel> channel, int deadline_ms);
  void MatchLostScan(const std::string& robot_id, const std::optional<PlanarTransform>& coarse,
                     std::function<void(absl::StatusOr<ScanRefinement>)> done) override;

 private:
  std::unique_ptr<semnav::mapping::v1::MappingService::Stub> stub_;
  int deadline_ms_;
};

}  // namespace semnav::reasoning
