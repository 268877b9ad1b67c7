// A small open world and camera for the simulated VLM's tests: a backpack 8 m ahead of a camera
// 1.5 m up, pitched 0.35 rad down, and the gateway's EROI codes printed into its frames.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "clients/sim/core/rgb_image.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/sensor_frame.h"
#include "clients/sim/core/view_renderer.h"
#include "clients/sim/core/world.h"
#include "services/reasoning/core/eroi_search.h"

namespace semnav::sim::vlm::testing {

inline BoxShape Cube(double x, double y, double edge) {
  BoxShape box;
  box.center = Eigen::Vector2d(x, y);
  box.size = Eigen::Vector3d(edge, edge, edge);
  return box;
}

// 40 x 40 m, a backpack at (8, 0), a bench at (8, 5), a road strip along y = -6.
inline World SearchWorld(bool wall_in_front = false) {
  World world;
  world.name = "vlm-test";
  world.bounds_min = Eigen::Vector2d(-20, -20);
  world.bounds_max = Eigen::Vector2d(20, 20);
  world.objects.push_back(
      ObjectInstance{"backpack-1", "backpack", Rgb{200, 40, 40}, Cube(8, 0, 1.0), ""});
  world.objects.push_back(
      ObjectInstance{"bench-1", "bench", Rgb{120, 80, 40}, Cube(8, 5, 1.0), ""});
  BoxShape road = Cube(0, -6, 1.0);
  road.size = Eigen::Vector3d(40, 3, 0.02);
  world.obstacles.push_back(Obstacle{"road", Rgb{60, 60, 60}, road});
  if (wall_in_front) {
    BoxShape wall = Cube(4, 0, 1.0);
    wall.size = Eigen::Vector3d(0.3, 6, 4);
    world.obstacles.push_back(Obstacle{"wall", Rgb{180, 180, 160}, wall});
  }
  StartPose start;
  world.starts.push_back(start);
  return world;
}

inline CameraIntrinsics Intrinsics() {
  return CameraIntrinsics{160, 120, 131.25, 131.25, 79.5, 59.5};
}

// Camera body (x forward, z up) at `position`, heading `yaw`, pitched `pitch` down.
inline Eigen::Quaterniond BodyOrientation(double yaw, double pitch = 0.35) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()));
}

inline Eigen::Isometry3d WorldFromOptical(const Eigen::Vector3d& position,
                                          const Eigen::Quaterniond& body) {
  Eigen::Matrix3d optical_from_body;
  optical_from_body << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = body.toRotationMatrix() * optical_from_body.transpose();
  pose.translation() = position;
  return pose;
}

// The frame the simulator would send (true pose = odometry pose).
inline SensorFrame Capture(const Scene& scene, const Eigen::Vector3d& position, double yaw,
                           uint64_t index) {
  SensorFrame frame;
  frame.index = index;
  frame.intrinsics = Intrinsics();
  frame.world_from_camera = WorldFromOptical(position, BodyOrientation(yaw));
  frame.odom_from_camera = frame.world_from_camera;
  const RenderedView view = RenderView(scene, frame.intrinsics, frame.world_from_camera, 0.1, 40.0);
  frame.rgb = RenderRgb(view, scene);
  return frame;
}

// The gateway's grid for the world: 3 m EROIs over its bounds.
inline reasoning::EroiSearchConfig GatewayEroi() {
  reasoning::EroiSearchConfig config;
  config.grid =
      reasoning::GridOverArea(config.grid, Eigen::Vector2d(-20, -20), Eigen::Vector2d(20, 20));
  return config;
}

inline reasoning::PinholeCamera Pinhole() {
  const CameraIntrinsics k = Intrinsics();
  return reasoning::PinholeCamera{k.fx, k.fy, k.cx, k.cy, k.width, k.height};
}

}  // namespace semnav::sim::vlm::testing
