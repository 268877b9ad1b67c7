#include "services/mapping/testing/synthetic_room.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace semnav::mapping::testing {
namespace {

constexpr double kNoHit = std::numeric_limits<double>::infinity();

// Entry distance of the ray into a solid box (slab method), kNoHit when it misses.
double EnterBox(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Box& b) {
  double t_near = 0.0;
  double t_far = kNoHit;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-12) {
      if (o[a] < b.min[a] || o[a] > b.max[a]) return kNoHit;
      continue;
    }
    double t0 = (b.min[a] - o[a]) / d[a];
    double t1 = (b.max[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  }
  return t_near <= t_far ? t_near : kNoHit;
}

// Exit distance of the ray from the room's inside (origin assumed inside).
double ExitRoom(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& size) {
  double t = kNoHit;
  for (int a = 0; a < 3; ++a) {
    if (d[a] > 1e-12) t = std::min(t, (size[a] - o[a]) / d[a]);
    if (d[a] < -1e-12) t = std::min(t, -o[a] / d[a]);
  }
  return t;
}

}  // namespace

std::vector<float> SyntheticRoom::RenderDepth(const Intrinsics& k, const CameraPose& pose) const {
  const Eigen::Matrix3d r = pose.orientation.toRotationMatrix();
  std::vector<float> depth(static_cast<size_t>(k.width) * k.height, 0.0f);
  for (int v = 0; v < k.height; ++v) {
    for (int u = 0; u < k.width; ++u) {
      // Camera ray with unit z, so the hit distance t equals the depth.
      const Eigen::Vector3d dir = r * Eigen::Vector3d((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
      double t = ExitRoom(pose.position, dir, size);
      for (const Box& b : boxes) t = std::min(t, EnterBox(pose.position, dir, b));
      if (std::isfinite(t)) depth[static_cast<size_t>(v) * k.width + u] = static_cast<float>(t);
    }
  }
  return depth;
}

Intrinsics Vga() { return Intrinsics{640, 480, 525.0, 525.0, 319.5, 239.5}; }

CameraPose LookAt(const Eigen::Vector3d& position, const Eigen::Vector3d& target) {
  const Eigen::Vector3d forward = (target - position).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross(right);
  Eigen::Matrix3d r;
  r.col(0) = right;
  r.col(1) = down;
  r.col(2) = forward;
  return CameraPose{position, Eigen::Quaterniond(r).normalized()};
}

SyntheticRoom StandardRoom() {
  SyntheticRoom room;
  room.boxes.push_back({{3.0, 1.0, 0.0}, {3.6, 1.6, 0.8}});
  room.boxes.push_back({{5.2, 3.0, 0.0}, {5.8, 3.8, 1.9}});
  return room;
}

CameraPose TurnedAt(const Eigen::Vector2d& at, double heading) {
  return LookAt({at.x(), at.y(), 1.2},
                {at.x() + 3.0 * std::cos(heading), at.y() + 3.0 * std::sin(heading), 0.8});
}

std::vector<CameraPose> RoomTour(const SyntheticRoom& room, int count) {
  std::vector<CameraPose> poses;
  for (int i = 0; i < count; ++i) {
    const double s = count > 1 ? static_cast<double>(i) / (count - 1) : 0.5;
    const Eigen::Vector3d position(0.8 + 1.6 * s, 0.6 + 0.4 * s, 1.2);
    const double angle = -0.6 + 1.8 * s;  // sweep from the right wall to the far-left corner
    const Eigen::Vector3d target(room.size.x(), room.size.y() * 0.5 + 3.0 * std::tan(angle) * 0.5,
                                 0.6);
    poses.push_back(LookAt(position, target));
  }
  return poses;
}

SensorFrame RenderFrame(const SyntheticRoom& room, const CameraPose& pose, int64_t stamp_ns,
                        DepthEncoding encoding) {
  SensorFrame frame;
  frame.robot_id = "robot-1";
  frame.stamp_ns = stamp_ns;
  frame.intrinsics = Vga();
  frame.pose = pose;
  frame.depth.width = frame.intrinsics.width;
  frame.depth.height = frame.intrinsics.height;
  frame.depth.encoding = encoding;
  const std::vector<float> metres = room.RenderDepth(frame.intrinsics, pose);
  if (encoding == DepthEncoding::kMillimetres16U) {
    std::vector<uint16_t> mm(metres.size());
    for (size_t i = 0; i < metres.size(); ++i) {
      mm[i] = static_cast<uint16_t>(std::min(65535.0f, std::round(metres[i] * 1000.0f)));
    }
    frame.depth.data.assign(reinterpret_cast<const char*>(mm.data()), mm.size() * sizeof(uint16_t));
  } else {
    frame.depth.data.assign(reinterpret_cast<const char*>(metres.data()),
                            metres.size() * sizeof(float));
  }
  return frame;
}

}  // namespace semnav::mapping::testing
