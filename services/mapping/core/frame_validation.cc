#include "services/mapping/core/frame_validation.h"

#include <cmath>
#include <cstddef>
#include <utility>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"

namespace semnav::mapping {
namespace {

constexpr double kUnitQuaternionTolerance = 1e-3;
// Focal lengths and principal points in pixels: outside these, rays (and so every lifted point)
// leave any mapped world.
constexpr double kMinFocalPx = 1.0;
constexpr double kMaxPixelCoordinate = 1e6;
// Per-frame lists: far above any real camera or detector, far below what would exhaust memory.
constexpr size_t kMaxDetections = 1024;
constexpr size_t kMaxEmbeddingLength = 4096;
// Embedding components: far above any model's, far below where a dot product overflows a float.
constexpr double kMaxEmbeddingValue = 1e6;
constexpr size_t kMaxLidarPoints = 1 << 20;

absl::Status CheckPosition(const Eigen::Vector3d& p, absl::string_view field) {
  return CheckPoint(p.x(), p.y(), p.z(), field, kMaxCoordinateM);
}

size_t BytesPerPixel(DepthEncoding encoding) {
  return encoding == DepthEncoding::kMillimetres16U ? 2 : 4;
}

absl::Status ValidateGeometry(const SensorFrame& frame) {
  const Intrinsics& k = frame.intrinsics;
  if (k.width <= 0) return InvalidField("intrinsics.width", "image size must be positive");
  if (k.height <= 0) return InvalidField("intrinsics.height", "image size must be positive");
  for (const auto& [value, field] :
       {std::pair{k.fx, "intrinsics.fx"}, std::pair{k.fy, "intrinsics.fy"}}) {
    if (absl::Status s = CheckRange(value, field, kMinFocalPx, kMaxPixelCoordinate); !s.ok()) {
      return s;
    }
  }
  for (const auto& [value, field] :
       {std::pair{k.cx, "intrinsics.cx"}, std::pair{k.cy, "intrinsics.cy"}}) {
    if (absl::Status s = CheckMagnitude(value, field, kMaxPixelCoordinate); !s.ok()) return s;
  }
  const DepthImage& d = frame.depth;
  if (d.encoding == DepthEncoding::kUnknown) {
    return InvalidField("depth.encoding",
                        "unknown encoding (expected 16UC1 millimetres or 32FC1 metres)");
  }
  if (d.width != k.width || d.height != k.height) {
    return InvalidField(d.width != k.width ? "depth.width" : "depth.height",
                        absl::StrCat("depth is ", d.width, "x", d.height, " but intrinsics are ",
                                     k.width, "x", k.height));
  }
  const size_t expected = static_cast<size_t>(d.width) * d.height * BytesPerPixel(d.encoding);
  if (d.data.size() != expected) {
    return InvalidField("depth.data",
                        absl::StrCat("has ", d.data.size(), " bytes, expected ", expected));
  }
  if (absl::Status s = CheckPosition(frame.pose.position, "pose.position"); !s.ok()) return s;
  const Eigen::Quaterniond& q = frame.pose.orientation;
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > kUnitQuaternionTolerance) {
    return InvalidField("pose.orientation", "must be a finite unit quaternion");
  }
  return absl::OkStatus();
}

absl::Status ValidateDetections(const SensorFrame& frame, int embedding_dim) {
  const int w = frame.intrinsics.width;
  const int h = frame.intrinsics.height;
  int dim = embedding_dim;
  if (absl::Status s = CheckCount(frame.detections.size(), "detections", kMaxDetections); !s.ok()) {
    return s;
  }
  for (size_t i = 0; i < frame.detections.size(); ++i) {
    const Detection& det = frame.detections[i];
    const std::string field = absl::StrCat("detections[", i, "]");
    if (det.label.empty()) return InvalidField(absl::StrCat(field, ".label"), "must not be empty");
    if (absl::Status s = CheckLength(det.label, absl::StrCat(field, ".label"), kMaxIdBytes);
        !s.ok()) {
      return s;
    }
    if (!(det.score >= 0.0 && det.score <= 1.0))
      return InvalidField(absl::StrCat(field, ".score"), "must be in [0, 1]");
    const PixelBox& b = det.box;
    const bool inside = b.x_min >= 0.0 && b.y_min >= 0.0 && b.x_max <= w && b.y_max <= h &&
                        b.x_min < b.x_max && b.y_min < b.y_max;
    if (!inside) {
      return InvalidField(absl::StrCat(field, ".box"),
                          absl::StrCat("must be a non-empty box inside the ", w, "x", h, " image"));
    }
    if (!det.mask.empty() && det.mask.size() != static_cast<size_t>(w) * h) {
      return InvalidField(absl::StrCat(field, ".mask"),
                          absl::StrCat("must have ", w * h, " pixels"));
    }
    if (det.embedding.empty()) continue;
    const std::string embedding_field = absl::StrCat(field, ".embedding");
    if (absl::Status s = CheckCount(det.embedding.size(), embedding_field, kMaxEmbeddingLength);
        !s.ok()) {
      return s;
    }
    for (size_t j = 0; j < det.embedding.size(); ++j) {
      if (absl::Status s = CheckMagnitude(
              det.embedding[j], absl::StrCat(embedding_field, "[", j, "]"), kMaxEmbeddingValue);
          !s.ok()) {
        return s;
      }
    }
    if (dim != 0 && static_cast<int>(det.embedding.size()) != dim) {
      return InvalidField(
          absl::StrCat(field, ".embedding"),
          absl::StrCat("length ", det.embedding.size(), " != map embedding length ", dim));
    }
    dim = static_cast<int>(det.embedding.size());
  }
  return absl::OkStatus();
}

}  // namespace

absl::Status ValidateFrame(const SensorFrame& frame, const ValidationContext& context) {
  if (frame.robot_id.empty()) return InvalidField("robot_id", "must not be empty");
  if (absl::Status s = CheckLength(frame.robot_id, "robot_id", kMaxIdBytes); !s.ok()) return s;
  if (context.last_stamp_ns.has_value() && frame.stamp_ns < *context.last_stamp_ns) {
    return FieldStatus(absl::StatusCode::kFailedPrecondition, "stamp",
                       absl::StrCat(frame.stamp_ns, " ns goes backwards for robot ", frame.robot_id,
                                    " (last accepted ", *context.last_stamp_ns, " ns)"),
                       "FAILED_PRECONDITION");
  }
  if (absl::Status s = ValidateGeometry(frame); !s.ok()) return s;
  if (absl::Status s = CheckCount(frame.lidar_points.size(), "lidar_points", kMaxLidarPoints);
      !s.ok()) {
    return s;
  }
  for (size_t i = 0; i < frame.lidar_points.size(); ++i) {
    if (absl::Status s = CheckPosition(frame.lidar_points[i].cast<double>(),
                                       absl::StrCat("lidar_points[", i, "]"));
        !s.ok()) {
      return s;
    }
  }
  return ValidateDetections(frame, context.embedding_dim);
}

}  // namespace semnav::mapping
