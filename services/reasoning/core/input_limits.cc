#include "services/reasoning/core/input_limits.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"

namespace semnav::reasoning {

std::size_t Utf8Chars(absl::string_view text) {
  std::size_t chars = 0;
  for (const char c : text) {
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++chars;
  }
  return chars;
}

absl::Status CheckInstruction(absl::string_view text, absl::string_view field) {
  // Bytes bound the characters from above: the count is only needed for long texts.
  if (text.size() <= kMaxInstructionChars) return absl::OkStatus();
  const std::size_t chars = Utf8Chars(text);
  if (chars <= kMaxInstructionChars) return absl::OkStatus();
  return InvalidField(field,
                      absl::StrCat("is ", chars, " characters, more than the limit of ",
                                   kMaxInstructionChars, " (starts '", Preview(text, 16), "')"));
}

absl::Status CheckPosition(const Eigen::Vector3d& position, absl::string_view field) {
  return CheckPoint(position.x(), position.y(), position.z(), field, kMaxCoordinateM);
}

absl::Status CheckRobotPose(const RobotPose& pose, absl::string_view field) {
  if (absl::Status status = CheckPosition(pose.position, field); !status.ok()) return status;
  return CheckFinite(pose.yaw, absl::StrCat(field, ".yaw"));
}

absl::Status CheckTargetSpec(const TargetSpec& target, absl::string_view field) {
  const std::pair<const std::string*, const char*> ids[] = {
      {&target.name, ".name"}, {&target.relation, ".relation"}, {&target.anchor, ".anchor"}};
  for (const auto& [value, name] : ids) {
    absl::Status status = CheckLength(*value, absl::StrCat(field, name), kMaxIdBytes);
    if (!status.ok()) return status;
  }
  if (absl::Status status = CheckInstruction(target.text, absl::StrCat(field, ".text"));
      !status.ok()) {
    return status;
  }
  const std::string colours_field = absl::StrCat(field, ".colours");
  if (absl::Status status = CheckCount(target.colours.size(), colours_field, kMaxTargetColours);
      !status.ok()) {
    return status;
  }
  for (std::size_t i = 0; i < target.colours.size(); ++i) {
    absl::Status status =
        CheckLength(target.colours[i], absl::StrCat(colours_field, "[", i, "]"), kMaxIdBytes);
    if (!status.ok()) return status;
  }
  return absl::OkStatus();
}

absl::Status CheckSearchArea(const SearchArea& area, absl::string_view field) {
  const std::pair<double, const char*> coordinates[] = {{area.min.x(), ".min_x"},
                                                        {area.min.y(), ".min_y"},
                                                        {area.max.x(), ".max_x"},
                                                        {area.max.y(), ".max_y"}};
  for (const auto& [value, name] : coordinates) {
    absl::Status status = CheckMagnitude(value, absl::StrCat(field, name), kMaxCoordinateM);
    if (!status.ok()) return status;
  }
  if (area.min.x() >= area.max.x() || area.min.y() >= area.max.y()) {
    return InvalidField(field, "min_x must be < max_x and min_y < max_y");
  }
  return absl::OkStatus();
}

absl::Status CheckCommand(const RobotCommand& command) {
  switch (command.kind) {
    case CommandKind::kNavigate: {
      if (absl::Status s = CheckPosition(command.goal, "goal"); !s.ok()) return s;
      if (absl::Status s = CheckFinite(command.goal_yaw, "goal_yaw"); !s.ok()) return s;
      if (absl::Status s = CheckRange(command.max_speed, "max_speed_mps", 0.0, kMaxSpeedMps);
          !s.ok()) {
        return s;
      }
      for (std::size_t i = 0; i < command.path.size(); ++i) {
        absl::Status s = CheckPosition(command.path[i], absl::StrCat("path[", i, "]"));
        if (!s.ok()) return s;
      }
      return absl::OkStatus();
    }
    case CommandKind::kRotate:
      if (absl::Status s =
              CheckMagnitude(command.angular_speed, "angular_speed_rps", kMaxAngularSpeedRps);
          !s.ok()) {
        return s;
      }
      [[fallthrough]];  // then what a hold is checked for
    case CommandKind::kHold:
      if (absl::Status s =
              CheckRange(command.camera_tilt_rad, "camera_tilt_rad", 0.0, kMaxCameraTiltRad);
          !s.ok()) {
        return s;
      }
      return CheckRange(command.duration_s, "duration_s", 0.0, kMaxCommandDurationS);
    case CommandKind::kStop:
      return absl::OkStatus();
  }
  return absl::OkStatus();
}

}  // namespace semnav::reasoning
