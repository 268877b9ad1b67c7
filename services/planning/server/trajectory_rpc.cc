#include "services/planning/server/trajectory_rpc.h"

#include "absl/strings/str_cat.h"
#include "services/common/status/grpc_status.h"
#include "services/common/status/value_checks.h"
#include "services/planning/core/trajectory.h"
#include "services/planning/server/grid_conversion.h"
#include "services/planning/server/request_checks.h"

namespace semnav::planning {

absl::Status SmoothTrajectoryOn(const semnav::common::v1::GridMap& grid, const std::string& field,
                                const semnav::planning::v1::SmoothTrajectoryRequest& request,
                                const TrajectoryConfig& config, int occupied_percent,
                                semnav::planning::v1::SmoothTrajectoryResponse* response) {
  if (request.path_size() < 2) {
    return FieldError(absl::StatusCode::kInvalidArgument, "path", "path needs at least 2 points");
  }
  if (absl::Status s = CheckCount(request.path_size(), "path", kMaxListItems); !s.ok()) return s;
  absl::StatusOr<GridFrame> frame = ReadGridFrame(grid, field);
  if (!frame.ok()) return frame.status();
  absl::StatusOr<PassabilityGrid> free = ToPassability(grid, {occupied_percent, false}, field);
  if (!free.ok()) return free.status();
  std::vector<Point2> path;
  for (int i = 0; i < request.path_size(); ++i) {
    const std::string name = absl::StrCat("path[", i, "]");
    absl::StatusOr<Cell> cell = frame->ToCell(request.path(i), name);
    if (!cell.ok()) return cell.status();
    if (free->at(*cell) == 0) {
      return FieldError(absl::StatusCode::kInvalidArgument, name, name + " is on a blocked cell");
    }
    path.push_back({request.path(i).x(), request.path(i).y()});
  }
  const GridGeometry geometry{frame->resolution, frame->origin_x, frame->origin_y};
  const std::vector<TrajectoryPoint> trajectory =
      AllocateTime(SmoothPath(*free, geometry, path, config.smoothing), config.limits);
  for (const TrajectoryPoint& p : trajectory) {
    semnav::planning::v1::TrajectoryPoint* out = response->add_points();
    out->mutable_pose()->set_x(p.x);
    out->mutable_pose()->set_y(p.y);
    out->mutable_pose()->set_yaw(p.yaw);
    out->set_speed_mps(p.speed);
    out->set_time_s(p.t);
  }
  response->set_duration_s(trajectory.back().t);
  return absl::OkStatus();
}

}  // namespace semnav::planning
