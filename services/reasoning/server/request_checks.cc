#include "services/reasoning/server/request_checks.h"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <tuple>
#include <utility>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"
#include "services/reasoning/core/input_limits.h"
#include "services/reasoning/server/proto_convert.h"

namespace semnav::reasoning {
namespace {

using IdField = std::pair<const std::string*, absl::string_view>;

// The first id longer than kMaxIdBytes, named.
absl::Status CheckIds(std::initializer_list<IdField> ids) {
  for (const auto& [value, field] : ids) {
    if (absl::Status status = CheckLength(*value, field, kMaxIdBytes); !status.ok()) return status;
  }
  return absl::OkStatus();
}

absl::Status CheckVector(const common::v1::Vector3& v, absl::string_view field, double max_abs) {
  return CheckPoint(v.x(), v.y(), v.z(), field, max_abs);
}

// Finite components, and unit length within 1e-3 (docs/protocol.md); all zero = unset, read as
// the identity.
absl::Status CheckOrientation(const common::v1::Quaternion& q, absl::string_view field) {
  const std::pair<double, const char*> parts[] = {
      {q.x(), ".x"}, {q.y(), ".y"}, {q.z(), ".z"}, {q.w(), ".w"}};
  for (const auto& [value, part] : parts) {
    if (absl::Status s = CheckFinite(value, absl::StrCat(field, part)); !s.ok()) return s;
  }
  const double norm = std::sqrt(q.x() * q.x() + q.y() * q.y() + q.z() * q.z() + q.w() * q.w());
  if (norm != 0.0 && std::abs(norm - 1.0) > 1e-3) {
    return InvalidField(field, absl::StrCat("must be a unit quaternion (norm ", norm, ")"));
  }
  return absl::OkStatus();
}

absl::Status CheckPose(const common::v1::Pose& pose, absl::string_view field) {
  if (absl::Status s =
          CheckVector(pose.position(), absl::StrCat(field, ".position"), kMaxCoordinateM);
      !s.ok()) {
    return s;
  }
  return CheckOrientation(pose.orientation(), absl::StrCat(field, ".orientation"));
}

// Task control shares its fields.
template <typename Request>
absl::Status CheckTaskControl(const Request& request) {
  return CheckIds({{&request.request_id(), "request_id"},
                   {&request.task_id(), "task_id"},
                   {&request.lease_id(), "lease_id"}});
}

}  // namespace

absl::StatusOr<double> DurationSeconds(const google::protobuf::Duration& duration,
                                       absl::string_view field) {
  if (std::abs(static_cast<int64_t>(duration.nanos())) >= 1000000000) {
    return InvalidField(field, "nanos must be within +-999,999,999");
  }
  const double seconds = static_cast<double>(duration.seconds()) + duration.nanos() * 1e-9;
  if (std::abs(seconds) > kMaxRequestDurationS) {
    return InvalidField(field, absl::StrCat("must be within +-", kMaxRequestDurationS, " s"));
  }
  return seconds;
}

absl::Status Validate(const api::SubmitInstructionRequest& request) {
  if (absl::Status s = CheckIds({{&request.request_id(), "request_id"},
                                 {&request.robot_id(), "robot_id"},
                                 {&request.lease_id(), "lease_id"}});
      !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckInstruction(request.instruction(), "instruction"); !s.ok()) return s;
  if (!request.has_search_area()) return absl::OkStatus();
  return FromProto(request.search_area()).status();
}

absl::Status Validate(const api::GetTaskRequest& request) {
  return CheckIds({{&request.task_id(), "task_id"}});
}

absl::Status Validate(const api::ListTasksRequest& request) {
  return CheckIds({{&request.robot_id(), "robot_id"}});
}

absl::Status Validate(const api::WatchTaskRequest& request) {
  return CheckIds({{&request.task_id(), "task_id"}});
}

absl::Status Validate(const api::CancelTaskRequest& request) {
  if (absl::Status s = CheckTaskControl(request); !s.ok()) return s;
  return CheckLength(request.reason(), "reason", kMaxTextBytes);
}

absl::Status Validate(const api::PauseTaskRequest& request) { return CheckTaskControl(request); }

absl::Status Validate(const api::ResumeTaskRequest& request) { return CheckTaskControl(request); }

absl::Status Validate(const api::AcquireLeaseRequest& request) {
  if (absl::Status s = CheckIds({{&request.request_id(), "request_id"},
                                 {&request.robot_id(), "robot_id"},
                                 {&request.holder(), "holder"}});
      !s.ok()) {
    return s;
  }
  return request.has_ttl() ? DurationSeconds(request.ttl(), "ttl").status() : absl::OkStatus();
}

absl::Status Validate(const api::RenewLeaseRequest& request) {
  if (absl::Status s = CheckIds({{&request.lease_id(), "lease_id"}}); !s.ok()) return s;
  return request.has_ttl() ? DurationSeconds(request.ttl(), "ttl").status() : absl::OkStatus();
}

absl::Status Validate(const api::ReleaseLeaseRequest& request) {
  return CheckIds({{&request.lease_id(), "lease_id"}});
}

absl::Status Validate(const api::EmergencyStopRequest& request) {
  if (absl::Status s =
          CheckIds({{&request.request_id(), "request_id"}, {&request.robot_id(), "robot_id"}});
      !s.ok()) {
    return s;
  }
  return CheckLength(request.reason(), "reason", kMaxTextBytes);
}

absl::Status Validate(const api::RelocalizeRobotRequest& request) {
  if (absl::Status s = CheckIds({{&request.request_id(), "request_id"},
                                 {&request.robot_id(), "robot_id"},
                                 {&request.lease_id(), "lease_id"}});
      !s.ok()) {
    return s;
  }
  return CheckLength(request.reason(), "reason", kMaxTextBytes);
}

absl::Status Validate(const api::ClearEmergencyStopRequest& request) {
  return CheckIds({{&request.request_id(), "request_id"},
                   {&request.robot_id(), "robot_id"},
                   {&request.lease_id(), "lease_id"}});
}

absl::Status Validate(const api::StreamFastTelemetryRequest& request) {
  return CheckIds({{&request.robot_id(), "robot_id"}});
}

absl::Status Validate(const api::StreamSlowTelemetryRequest& request) {
  if (absl::Status s = CheckIds({{&request.robot_id(), "robot_id"}}); !s.ok()) return s;
  return request.has_period() ? DurationSeconds(request.period(), "period").status()
                              : absl::OkStatus();
}

absl::Status Validate(const api::StreamEventsRequest& request) {
  return CheckIds({{&request.robot_id(), "robot_id"}});
}

absl::Status Validate(const api::ListEventsRequest& request) {
  return CheckIds({{&request.robot_id(), "robot_id"}, {&request.task_id(), "task_id"}});
}

absl::Status Validate(const api::DecomposeInstructionRequest& request) {
  return CheckInstruction(request.instruction(), "instruction");
}

absl::Status Validate(const api::ResolveTargetRequest& request) {
  if (absl::Status s = CheckIds({{&request.robot_id(), "robot_id"}}); !s.ok()) return s;
  if (absl::Status s = CheckInstruction(request.text(), "text"); !s.ok()) return s;
  if (!request.has_target()) return absl::OkStatus();
  // Counted before the copy into the core type, so a million colours are never copied.
  if (absl::Status s =
          CheckCount(request.target().colours_size(), "target.colours", kMaxTargetColours);
      !s.ok()) {
    return s;
  }
  return CheckTargetSpec(FromProto(request.target()), "target");
}

absl::Status Validate(const api::SessionHello& hello) {
  if (hello.robot_id().empty()) return InvalidField("hello.robot_id", "is required");
  if (absl::Status s = CheckLength(hello.robot_id(), "hello.robot_id", kMaxRobotIdBytes); !s.ok())
    return s;
  if (absl::Status s = CheckLength(hello.software_version(), "hello.software_version", kMaxIdBytes);
      !s.ok()) {
    return s;
  }
  const api::Capabilities& caps = hello.capabilities();
  if (absl::Status s =
          CheckCount(caps.modes_size(), "hello.capabilities.modes", kMaxLocomotionModes);
      !s.ok()) {
    return s;
  }
  for (int i = 0; i < caps.modes_size(); ++i) {
    if (!api::LocomotionMode_IsValid(caps.modes(i))) {
      return InvalidField(absl::StrCat("hello.capabilities.modes[", i, "]"),
                          absl::StrCat("unknown mode ", caps.modes(i)));
    }
  }
  const std::tuple<double, const char*, double> limits[] = {
      {caps.max_linear_speed_mps(), "hello.capabilities.max_linear_speed_mps", kMaxSpeedMps},
      {caps.max_angular_speed_rps(), "hello.capabilities.max_angular_speed_rps",
       kMaxAngularSpeedRps},
      {caps.max_vertical_speed_mps(), "hello.capabilities.max_vertical_speed_mps", kMaxSpeedMps},
      {caps.footprint_radius_m(), "hello.capabilities.footprint_radius_m", kMaxFootprintRadiusM},
      {caps.camera_tilt_max_rad(), "hello.capabilities.camera_tilt_max_rad", kMaxCameraTiltRad}};
  for (const auto& [value, field, max] : limits) {
    if (absl::Status s = CheckRange(value, field, 0.0, max); !s.ok()) return s;
  }
  return absl::OkStatus();
}

absl::Status Validate(const api::CommandFeedback& feedback) {
  // Every door refuses numbers it does not know, enums included (as planning does).
  if (!api::FeedbackKind_IsValid(feedback.kind()))
    return InvalidField("feedback.kind", "unknown kind");
  return CheckLength(feedback.detail(), "feedback.detail", kMaxTextBytes);
}

absl::Status Validate(const api::CameraFrame& frame) {
  const common::v1::CameraIntrinsics& k = frame.intrinsics();
  if (k.width() > kMaxCameraSide || k.height() > kMaxCameraSide) {
    return InvalidField("camera.intrinsics.width",
                        absl::StrCat("sides must be <= ", kMaxCameraSide));
  }
  if (frame.image().width() > kMaxCameraSide || frame.image().height() > kMaxCameraSide) {
    return InvalidField("camera.image.width", absl::StrCat("sides must be <= ", kMaxCameraSide));
  }
  const std::pair<double, const char*> intrinsics[] = {{k.fx(), "camera.intrinsics.fx"},
                                                       {k.fy(), "camera.intrinsics.fy"},
                                                       {k.cx(), "camera.intrinsics.cx"},
                                                       {k.cy(), "camera.intrinsics.cy"}};
  for (const auto& [value, field] : intrinsics) {
    if (absl::Status s = CheckMagnitude(value, field, kMaxFocalLengthPx); !s.ok()) return s;
  }
  if (!common::v1::ImageEncoding_IsValid(frame.image().encoding())) {
    return InvalidField("camera.image.encoding", "unknown encoding");
  }
  return CheckPose(frame.camera_pose(), "camera.camera_pose");
}

absl::StatusOr<RobotPose> ValidatedPose(const api::RobotState& state) {
  if (absl::Status s = CheckLength(state.header().frame_id(), "state.header.frame_id", kMaxIdBytes);
      !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckLength(state.header().robot_id(), "state.header.robot_id", kMaxIdBytes);
      !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckPose(state.pose(), "state.pose"); !s.ok()) return s;
  if (absl::Status s = CheckVector(state.velocity(), "state.velocity", kMaxSpeedMps); !s.ok())
    return s;
  if (!api::LocomotionMode_IsValid(state.mode())) {
    return InvalidField("state.mode", absl::StrCat("unknown mode ", state.mode()));
  }
  if (!api::LocalizationStatus_IsValid(state.localization())) {
    return InvalidField("state.localization",
                        absl::StrCat("unknown status ", state.localization()));
  }
  // In [0, 1]; any negative value means unknown.
  const double lowest = std::numeric_limits<double>::lowest();
  if (absl::Status s = CheckRange(state.battery_fraction(), "state.battery_fraction", lowest, 1.0);
      !s.ok()) {
    return s;
  }
  RobotPose pose = FromProto(state);
  // Belt and braces: a valid quaternion gives a finite yaw.
  if (absl::Status s = CheckFinite(pose.yaw, "state.pose.orientation"); !s.ok()) return s;
  return pose;
}

}  // namespace semnav::reasoning
