// The gateway's request doors: every OperatorService request and every robot session message is
// checked here before it reaches the hub's state (ids within kMaxIdBytes, instructions within
// kMaxInstructionChars, free text within kMaxTextBytes, numbers finite and sane). Each failure
// is INVALID_ARGUMENT naming the dotted field path; a refused request changes nothing.
#pragma once

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "google/protobuf/duration.pb.h"
#include "semnav/reasoning/v1/operator.pb.h"
#include "semnav/reasoning/v1/robot_session.pb.h"
#include "services/reasoning/core/robot_types.h"

namespace semnav::reasoning {

namespace api = ::semnav::reasoning::v1;

// Longest lease TTL and telemetry period a request may ask for before the service's own bounds
// apply; guards the Duration arithmetic.
inline constexpr double kMaxRequestDurationS = 24 * 3600.0;
// Motion modes one hello may list (there are four).
inline constexpr int kMaxLocomotionModes = 8;
// Camera images the EROI search accepts, pixels per side.
inline constexpr uint32_t kMaxCameraSide = 8192;
// A robot's footprint radius, metres, and camera intrinsics (fx, fy, cx, cy), pixels.
inline constexpr double kMaxFootprintRadiusM = 100.0;
inline constexpr double kMaxFocalLengthPx = 1e6;

absl::Status Validate(const api::SubmitInstructionRequest& request);
absl::Status Validate(const api::GetTaskRequest& request);
absl::Status Validate(const api::ListTasksRequest& request);
absl::Status Validate(const api::WatchTaskRequest& request);
absl::Status Validate(const api::CancelTaskRequest& request);
absl::Status Validate(const api::PauseTaskRequest& request);
absl::Status Validate(const api::ResumeTaskRequest& request);
absl::Status Validate(const api::AcquireLeaseRequest& request);
absl::Status Validate(const api::RenewLeaseRequest& request);
absl::Status Validate(const api::ReleaseLeaseRequest& request);
absl::Status Validate(const api::EmergencyStopRequest& request);
absl::Status Validate(const api::RelocalizeRobotRequest& request);
absl::Status Validate(const api::ClearEmergencyStopRequest& request);
absl::Status Validate(const api::StreamFastTelemetryRequest& request);
absl::Status Validate(const api::StreamSlowTelemetryRequest& request);
absl::Status Validate(const api::StreamEventsRequest& request);
absl::Status Validate(const api::ListEventsRequest& request);
absl::Status Validate(const api::DecomposeInstructionRequest& request);
absl::Status Validate(const api::ResolveTargetRequest& request);

// Robot session messages; fields are named from the ConnectRequest ("hello.robot_id",
// "state.pose.position.x", "camera.camera_pose.orientation").
absl::Status Validate(const api::SessionHello& hello);
absl::Status Validate(const api::CommandFeedback& feedback);
absl::Status Validate(const api::CameraFrame& frame);
// The pose of a robot state, after checking every field of the state.
absl::StatusOr<RobotPose> ValidatedPose(const api::RobotState& state);

// Seconds of a Duration, INVALID_ARGUMENT naming `field` when it is malformed or beyond
// kMaxRequestDurationS (either sign).
absl::StatusOr<double> DurationSeconds(const google::protobuf::Duration& duration,
                                       absl::string_view field);

}  // namespace semnav::reasoning
