// What the gateway accepts from operators and robots, checked where a core value is built from a
// request, and again where a robot command is built: no code path may send a robot a non-finite
// or absurd goal. Every failure is InvalidField(field, why) naming the dotted field path.
#pragma once

#include <cstddef>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"
#include "services/common/status/value_checks.h"
#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/robot_types.h"
#include "services/reasoning/core/subgoal.h"

namespace semnav::reasoning {

// Instructions and free-text targets: Unicode characters (code points), like the dashboard's
// input maxlength; 1000 characters are at most 4000 UTF-8 bytes, within kMaxTextBytes.
inline constexpr std::size_t kMaxInstructionChars = 1000;
// A robot's hello.robot_id (documented in robot_session.proto); other ids use kMaxIdBytes.
inline constexpr std::size_t kMaxRobotIdBytes = 128;
// Colours one target may name.
inline constexpr std::size_t kMaxTargetColours = 16;
// Speeds a robot reports or is sent, m/s and rad/s: beyond any robot semnav drives.
inline constexpr double kMaxSpeedMps = 100.0;
inline constexpr double kMaxAngularSpeedRps = 100.0;
// A camera tilt up from the robot's default view, rad (straight up from level).
inline constexpr double kMaxCameraTiltRad = 1.5707963267948966;
// Rotate / hold durations sent to a robot, seconds.
inline constexpr double kMaxCommandDurationS = 24 * 3600.0;

// Unicode characters of UTF-8 text (bytes that do not continue a sequence).
std::size_t Utf8Chars(absl::string_view text);
// At most kMaxInstructionChars characters.
absl::Status CheckInstruction(absl::string_view text, absl::string_view field);
// Finite and within kMaxCoordinateM on every axis; names "<field>.x" etc.
absl::Status CheckPosition(const Eigen::Vector3d& position, absl::string_view field);
// Position as above and a finite yaw ("<field>.yaw").
absl::Status CheckRobotPose(const RobotPose& pose, absl::string_view field);
// Names, relation and anchor within kMaxIdBytes, text within kMaxInstructionChars, at most
// kMaxTargetColours colours of kMaxIdBytes each ("<field>.colours[2]").
absl::Status CheckTargetSpec(const TargetSpec& target, absl::string_view field);
// Finite coordinates within kMaxCoordinateM ("<field>.min_x" ...) and min < max on both axes
// (naming `field`).
absl::Status CheckSearchArea(const SearchArea& area, absl::string_view field);
// Every number a command carries is finite and sane: goal and path within kMaxCoordinateM,
// yaw finite, speeds within kMaxSpeedMps / kMaxAngularSpeedRps and not negative (linear),
// durations within [0, kMaxCommandDurationS]. Fields are named "goal.x", "path[3].y", ...
absl::Status CheckCommand(const RobotCommand& command);

}  // namespace semnav::reasoning
