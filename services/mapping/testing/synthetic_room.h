#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "services/mapping/core/sensor_frame.h"

namespace semnav::mapping::testing {

// Axis-aligned solid box in the map frame (metres).
struct Box {
  Eigen::Vector3d min;
  Eigen::Vector3d max;
};

// A closed room [0, size.x] x [0, size.y] x [0, size.z] (floor, walls, ceiling) with solid boxes
// inside, rendered by exact ray casting. Used by tests, the contract test and the benchmark.
struct SyntheticRoom {
  Eigen::Vector3d size{6.0, 4.0, 2.5};
  std::vector<Box> boxes;

  // Depth (metres, 0 = no hit) of the first surface along the ray of each pixel.
  std::vector<float> RenderDepth(const Intrinsics& k, const CameraPose& pose) const;
};

// A 640x480 camera with a 525 px focal length (Kinect-like).
Intrinsics Vga();

// Optical-frame pose at `position` looking at `target`, z up in the map.
CameraPose LookAt(const Eigen::Vector3d& position, const Eigen::Vector3d& target);

// The standard test room: 6 x 4 x 2.5 m with a table-height box and a tall cabinet.
SyntheticRoom StandardRoom();

// A camera turning in place: 1.2 m high at `at`, looking along `heading` (radians) at a point 3 m
// out and 0.8 m high.
CameraPose TurnedAt(const Eigen::Vector2d& at, double heading);

// `count` poses at 1.2 m height along the room's long axis, each looking at a different wall point.
std::vector<CameraPose> RoomTour(const SyntheticRoom& room, int count);

// A validated-shape frame with 32FC1 or 16UC1 depth rendered from `room`.
SensorFrame RenderFrame(const SyntheticRoom& room, const CameraPose& pose, int64_t stamp_ns,
                        DepthEncoding encoding = DepthEncoding::kMetres32F);

}  // namespace semnav::mapping::testing
