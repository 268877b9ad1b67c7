// Conversions between the gateway's core values and its API messages.
#pragma once

#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "semnav/reasoning/v1/operator.pb.h"
#include "semnav/reasoning/v1/robot_session.pb.h"
#include "semnav/reasoning/v1/task.pb.h"
#include "services/reasoning/core/event_log.h"
#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/exploration_strategy.h"
#include "services/reasoning/core/robot_types.h"
#include "services/reasoning/core/subgoal.h"
#include "services/reasoning/core/task_executor.h"
#include "services/reasoning/core/task_registry.h"

namespace semnav::reasoning {

namespace api = ::semnav::reasoning::v1;

api::TargetSpec ToProto(const TargetSpec& target);
TargetSpec FromProto(const api::TargetSpec& target);
api::Subgoal ToProto(const Subgoal& subgoal);
api::RobotCommand ToProto(const RobotCommand& command, uint64_t session_command_id,
                          const std::string& task_id);
// A fly-roll robot's navigate path: each waypoint's mode says how the segment ending there is
// travelled, AIR when it starts or ends above the floor (take-off, flight, landing), GROUND
// otherwise. The first segment starts where the first waypoint is (the robot's position).
void SetFlyRollModes(api::NavigateAction* navigate);
api::Event ToProto(const LoggedEvent& event);
api::TaskStatus ToProto(TaskState state);
// The operator's TaskSnapshot (the only place a task becomes a message).
api::TaskSnapshot ToProto(const TaskView& view);
// Pose and yaw (about z) from the robot's state message.
RobotPose FromProto(const api::RobotState& state);
// A pose's position and yaw about z (roll and pitch dropped), and back (a rotation about z).
RobotPose FromProto(const common::v1::Pose& pose);
common::v1::Pose ToProtoPose(const RobotPose& pose);
// INVALID_ARGUMENT naming the coordinate ("search_area.min_x") when it is not finite or beyond
// kMaxCoordinateM, or naming `search_area` when min >= max.
absl::StatusOr<SearchArea> FromProto(const api::SearchArea& area);
api::SearchArea ToProto(const SearchArea& area);
// nullopt for ACCEPTED and UNSPECIFIED, which need no reaction.
std::optional<RobotFeedback> FromProto(api::FeedbackKind kind);
api::ResolutionPath ToProto(ResolutionPath path);
// nullopt for UNSPECIFIED (the configured default) and for values the caller has checked away.
std::optional<ExplorationStrategy> StrategyFromProto(api::ExplorationStrategy strategy);

}  // namespace semnav::reasoning
