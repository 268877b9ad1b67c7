#include "services/planning/server/request_checks.h"

#include "absl/strings/str_cat.h"
#include "services/common/status/value_checks.h"

namespace semnav::planning {

absl::Status CheckPose2D(const semnav::common::v1::Pose2D& pose, absl::string_view field) {
  if (absl::Status s = CheckMagnitude(pose.x(), absl::StrCat(field, ".x"), kMaxCoordinateM);
      !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckMagnitude(pose.y(), absl::StrCat(field, ".y"), kMaxCoordinateM);
      !s.ok()) {
    return s;
  }
  return CheckMagnitude(pose.yaw(), absl::StrCat(field, ".yaw"), kMaxAngleRad);
}

absl::Status CheckScore(double value, absl::string_view field) {
  return CheckMagnitude(value, field, kMaxScore);
}

absl::Status CheckSemantics(const semnav::planning::v1::SemanticContext& semantics,
                            absl::string_view field) {
  const std::string objects = absl::StrCat(field, ".objects");
  if (absl::Status s = CheckCount(semantics.objects_size(), objects, kMaxListItems); !s.ok()) {
    return s;
  }
  for (int i = 0; i < semantics.objects_size(); ++i) {
    const auto& object = semantics.objects(i);
    const std::string at = absl::StrCat(objects, "[", i, "]");
    if (absl::Status s = CheckLength(object.label(), at + ".label", kMaxIdBytes); !s.ok()) return s;
    if (absl::Status s = CheckPose2D(object.position(), at + ".position"); !s.ok()) return s;
    if (absl::Status s = CheckScore(object.relevance(), at + ".relevance"); !s.ok()) return s;
    if (absl::Status s = CheckScore(object.relation(), at + ".relation"); !s.ok()) return s;
    if (absl::Status s = CheckScore(object.cooccurrence(), at + ".cooccurrence"); !s.ok()) return s;
  }
  const std::string visited = absl::StrCat(field, ".visited");
  if (absl::Status s = CheckCount(semantics.visited_size(), visited, kMaxListItems); !s.ok()) {
    return s;
  }
  for (int i = 0; i < semantics.visited_size(); ++i) {
    if (absl::Status s = CheckPose2D(semantics.visited(i), absl::StrCat(visited, "[", i, "]"));
        !s.ok()) {
      return s;
    }
  }
  return absl::OkStatus();
}

}  // namespace semnav::planning
