#pragma once

#include "clients/sim/core/world.h"

// Small hand-made worlds shared by the unit tests.
namespace semnav::sim::testing {

// A 10 x 10 m open square centred on the origin with one robot start at the origin.
inline World OpenWorld() {
  World world;
  world.name = "open";
  world.bounds_min = Eigen::Vector2d(-5, -5);
  world.bounds_max = Eigen::Vector2d(5, 5);
  world.starts.push_back(StartPose{});
  return world;
}

inline BoxShape Box(double x, double y, double sx, double sy, double sz, double yaw = 0.0) {
  BoxShape box;
  box.center = Eigen::Vector2d(x, y);
  box.size = Eigen::Vector3d(sx, sy, sz);
  box.yaw = yaw;
  return box;
}

inline ObjectInstance Object(const std::string& id, const std::string& label, BoxShape box) {
  return ObjectInstance{id, label, Rgb{200, 50, 50}, box, ""};
}

}  // namespace semnav::sim::testing
