#include "services/planning/server/plan_response.h"

#include <cmath>

#include "services/common/status/grpc_status.h"
#include "services/planning/core/plan_failure.h"

namespace semnav::planning {
namespace {

namespace pb = semnav::planning::v1;

// Waypoints as map-frame poses, each heading along its outgoing leg.
void FillPath(const GridFrame& frame, const std::vector<Cell>& waypoints,
              pb::PlanPathResponse* response) {
  double yaw = 0.0;
  for (size_t i = 0; i < waypoints.size(); ++i) {
    semnav::common::v1::Pose2D pose = frame.ToPose(waypoints[i]);
    if (i + 1 < waypoints.size()) {
      yaw = std::atan2(waypoints[i + 1].y - waypoints[i].y, waypoints[i + 1].x - waypoints[i].x);
    }
    pose.set_yaw(yaw);
    *response->add_path() = pose;
  }
}

pb::PlanFailureReason ReasonOf(PlanFailure failure) {
  switch (failure) {
    case PlanFailure::kStartOccupied:
      return pb::PLAN_FAILURE_REASON_START_OCCUPIED;
    case PlanFailure::kGoalOccupied:
      return pb::PLAN_FAILURE_REASON_GOAL_OCCUPIED;
    case PlanFailure::kNoPath:
      return pb::PLAN_FAILURE_REASON_NO_PATH;
    case PlanFailure::kTimeout:
      return pb::PLAN_FAILURE_REASON_TIMEOUT;
    case PlanFailure::kCancelled:
      return pb::PLAN_FAILURE_REASON_CANCELLED;
  }
  return pb::PLAN_FAILURE_REASON_UNSPECIFIED;
}

}  // namespace

void FillResponse(const GridFrame& frame, const GridPlanResult& result,
                  pb::PlanPathResponse* response) {
  FillPath(frame, result.path.waypoints, response);
  const double length = result.path.length_cells * frame.resolution;
  response->set_length_m(length);
  response->set_roll_m(length);
  pb::PathSegment* segment = response->add_segments();
  segment->set_first_point(0);
  segment->set_last_point(static_cast<uint32_t>(result.path.waypoints.size() - 1));
  segment->set_mode(pb::MOTION_MODE_ROLLING);
  segment->set_length_m(length);
  *response->mutable_planned_goal() = frame.ToPose(result.planned_goal);
  response->set_goal_adjusted(result.goal_adjusted);
  response->set_alternative_used(result.alternative_used);
  response->set_adjustment_reason(result.adjustment_reason);
  response->set_low_probability_cells_used(result.low_probability_cells_used);
  response->set_start_adjusted(result.start_adjusted);
  *response->mutable_planned_start() = frame.ToPose(result.planned_start);
  response->set_grid_padded(result.grid_padded);
  response->set_expansions(static_cast<uint32_t>(result.path.expansions));
}

void FillResponse(const GridFrame& frame, const MultiModalPath& path, const FlightHeights& heights,
                  pb::PlanPathResponse* response) {
  FillPath(frame, path.waypoints, response);
  response->set_length_m(path.length_m);
  response->set_fly_m(path.fly_m);
  response->set_roll_m(path.roll_m);
  response->set_energy_j(path.energy_j);
  response->set_mode_switches(static_cast<uint32_t>(path.switches));
  for (const ModalSegment& s : path.segments) {
    pb::PathSegment* segment = response->add_segments();
    segment->set_first_point(static_cast<uint32_t>(s.first_point));
    segment->set_last_point(static_cast<uint32_t>(s.last_point));
    segment->set_mode(s.mode == MotionMode::kFlying ? pb::MOTION_MODE_FLYING
                                                    : pb::MOTION_MODE_ROLLING);
    segment->set_length_m(s.length_m);
    segment->set_energy_j(s.energy_j);
    segment->set_altitude_m(
        FlightAltitude(s.top, heights.foot_m, heights.ceiling_m, heights.margin_m));
  }
  *response->mutable_planned_goal() = frame.ToPose(path.waypoints.back());
  response->set_expansions(static_cast<uint32_t>(path.expansions));
}

void AttachPlanFailure(absl::Status& status, Cell start, Cell goal) {
  const std::optional<PlanFailure> failure = PlanFailureOf(status);
  if (!failure) return;
  pb::PlanFailureDetail detail;
  detail.set_reason(ReasonOf(*failure));
  detail.set_start_column(static_cast<uint32_t>(start.x));
  detail.set_start_row(static_cast<uint32_t>(start.y));
  detail.set_goal_column(static_cast<uint32_t>(goal.x));
  detail.set_goal_row(static_cast<uint32_t>(goal.y));
  AttachDetail(status, detail);
}

}  // namespace semnav::planning
