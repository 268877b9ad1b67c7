#include "services/mapping/core/frame_validation.h"

#include <cmath>
#include <cstddef>

#include "absl/strings/str_cat.h"

namespace semnav::mapping {
namespace {

constexpr double kUnitQuaternionTolerance = 1e-3;

absl::Status Invalid(absl::string_view field, absl::string_view why) {
  return absl::InvalidArgumentError(absl::StrCat(field, ": ", why));
}

size_t BytesPerPixel(DepthEncoding encoding) {
  return encoding == DepthEncoding::kMillimetres16U ? 2 : 4;
}

absl::Status ValidateGeometry(const SensorFrame& frame) {
  const Intrinsics& k = frame.intrinsics;
  if (k.width <= 0 || k.height <= 0) return Invalid("intrinsics.width", "image size must be positive");
  if (!(k.fx > 0.0) || !(k.fy > 0.0) || !std::isfinite(k.fx) || !std::isfinite(k.fy)) {
    return Invalid("intrinsics.fx", "focal lengths must be finite and positive");
  }
  if (!std::isfinite(k.cx) || !std::isfinite(k.cy)) return Invalid("intrinsics.cx", "must be finite");
  const DepthImage& d = frame.depth;
  if (d.encoding == DepthEncoding::kUnknown) {
    return Invalid("depth.encoding", "unknown encoding (expected 16UC1 millimetres or 32FC1 metres)");
  }
  if (d.width != k.width || d.height != k.height) {
    return Invalid("depth.width", absl::StrCat("depth is ", d.width, "x", d.height,
                                               " but intrinsics are ", k.width, "x", k.height));
  }
  const size_t expected = static_cast<size_t>(d.width) * d.height * BytesPerPixel(d.encoding);
  if (d.data.size() != expected) {
    return Invalid("depth.data", absl::StrCat("has ", d.data.size(), " bytes, expected ", expected));
  }
  const Eigen::Vector3d& p = frame.pose.position;
  if (!p.allFinite()) return Invalid("pose.position", "must be finite");
  const Eigen::Quaterniond& q = frame.pose.orientation;
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > kUnitQuaternionTolerance) {
    return Invalid("pose.orientation", "must be a finite unit quaternion");
  }
  return absl::OkStatus();
}

absl::Status ValidateDetections(const SensorFrame& frame, int embedding_dim) {
  const int w = frame.intrinsics.width;
  const int h = frame.intrinsics.height;
  int dim = embedding_dim;
  for (size_t i = 0; i < frame.detections.size(); ++i) {
    const Detection& det = frame.detections[i];
    const std::string field = absl::StrCat("detections[", i, "]");
    if (det.label.empty()) return Invalid(absl::StrCat(field, ".label"), "must not be empty");
    if (!(det.score >= 0.0 && det.score <= 1.0)) return Invalid(absl::StrCat(field, ".score"), "must be in [0, 1]");
    const PixelBox& b = det.box;
    const bool inside = b.x_min >= 0.0 && b.y_min >= 0.0 && b.x_max <= w && b.y_max <= h &&
                        b.x_min < b.x_max && b.y_min < b.y_max;
    if (!inside) {
      return Invalid(absl::StrCat(field, ".box"), absl::StrCat("must be a non-empty box inside the ", w, "x", h, " image"));
    }
    if (!det.mask.empty() && det.mask.size() != static_cast<size_t>(w) * h) {
      return Invalid(absl::StrCat(field, ".mask"), absl::StrCat("must have ", w * h, " pixels"));
    }
    if (det.embedding.empty()) continue;
    if (dim != 0 && static_cast<int>(det.embedding.size()) != dim) {
      return Invalid(absl::StrCat(field, ".embedding"),
                     absl::StrCat("length ", det.embedding.size(), " != map embedding length ", dim));
    }
    dim = static_cast<int>(det.embedding.size());
  }
  return absl::OkStatus();
}

}  // namespace

absl::Status ValidateFrame(const SensorFrame& frame, const ValidationContext& context) {
  if (frame.robot_id.empty()) return Invalid("robot_id", "must not be empty");
  if (context.last_stamp_ns.has_value() && frame.stamp_ns < *context.last_stamp_ns) {
    return absl::FailedPreconditionError(absl::StrCat(
        "stamp: ", frame.stamp_ns, " ns goes backwards for robot ", frame.robot_id,
        " (last accepted ", *context.last_stamp_ns, " ns)"));
  }
  if (absl::Status s = ValidateGeometry(frame); !s.ok()) return s;
  return ValidateDetections(frame, context.embedding_dim);
}

}  // namespace semnav::mapping
